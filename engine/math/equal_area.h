// Clarberg's equal-area mapping between the unit square and the unit sphere (P. Clarberg
// 2008, "Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD", JGT 13(3)), in the form
// pbrt-v4 uses for its environment maps (pbrt-v4 3.8.3, EqualAreaSquareToSphere and
// EqualAreaSphereToSquare): the square's centre is +z, its four corners -z, and the
// diamond |u| + |v| = 1 (in [-1,1]^2 coordinates) the equator. Areas are preserved, so
// every texel of a square image covers the same solid angle, 4 pi / texels.
#pragma once
#include <algorithm>
#include <cmath>
#include <photon/vec.h>

namespace photon {

// p in [0,1]^2 to a unit direction.
inline Vec3 equalAreaSquareToSphere(Vec2 p) {
    const float u = 2 * p.x - 1, v = 2 * p.y - 1;
    const float up = std::abs(u), vp = std::abs(v);
    // Signed distance from the diamond: positive inside (the +z hemisphere).
    const float signedDistance = 1 - (up + vp);
    const float r = 1 - std::abs(signedDistance);
    // The angle about z within the quadrant, from the position along the diamond's edge.
    const float phi = (r == 0 ? 1 : (vp - up) / r + 1) * (kPi / 4);
    const float z = std::copysign(1 - r * r, signedDistance);
    const float cosPhi = std::copysign(std::cos(phi), u), sinPhi = std::copysign(std::sin(phi), v);
    const float s = r * std::sqrt(std::max(0.0f, 2 - r * r));
    return {cosPhi * s, sinPhi * s, z};
}

// The inverse: a unit direction to [0,1]^2.
inline Vec2 equalAreaSphereToSquare(Vec3 d) {
    const float x = std::abs(d.x), y = std::abs(d.y), z = std::abs(d.z);
    const float r = std::sqrt(std::max(0.0f, 1 - z));
    const float a = std::max(x, y), b = std::min(x, y);
    // phi in [0, 1]: the angle about z in the quadrant, in quarter turns from the nearer axis.
    float phi = a == 0 ? 0 : std::atan(b / a) * (2 / kPi);
    if (x < y) phi = 1 - phi;
    float v = phi * r, u = r - v;
    if (d.z < 0) {  // the lower hemisphere is folded out into the square's corners
        std::swap(u, v);
        u = 1 - u;
        v = 1 - v;
    }
    u = std::copysign(u, d.x);
    v = std::copysign(v, d.y);
    return {(u + 1) * 0.5f, (v + 1) * 0.5f};
}

// The texel a texel index outside a width x height equal-area image stands for, by the
// square's folds (pbrt-v4's octahedral-sphere wrap, Image::RemapPixelCoords): crossing the
// left or right edge lands in the same column mirrored top to bottom, crossing the top or
// bottom edge in the same row mirrored left to right, since each edge folds about its
// midpoint onto itself. Mirrored about the edge itself (-1 -> 0), so the texel returned is
// the one across the edge.
struct TexelIndex {
    int x, y;
};
inline TexelIndex wrapEqualAreaTexel(TexelIndex t, int width, int height) {
    if (t.x < 0) {
        t.x = -1 - t.x;
        t.y = height - 1 - t.y;
    } else if (t.x >= width) {
        t.x = 2 * width - 1 - t.x;
        t.y = height - 1 - t.y;
    }
    if (t.y < 0) {
        t.x = width - 1 - t.x;
        t.y = -1 - t.y;
    } else if (t.y >= height) {
        t.x = width - 1 - t.x;
        t.y = 2 * height - 1 - t.y;
    }
    return {std::clamp(t.x, 0, width - 1), std::clamp(t.y, 0, height - 1)};
}

// The same folds for a point of the square a little outside [0,1]^2 (pbrt-v4's
// WrapEqualAreaSquare): the point across the edge it crossed, inside [0,1]^2.
inline Vec2 wrapEqualAreaSquare(Vec2 p) {
    if (p.x < 0) p = {-p.x, 1 - p.y};
    else if (p.x > 1) p = {2 - p.x, 1 - p.y};
    if (p.y < 0) p = {1 - p.x, -p.y};
    else if (p.y > 1) p = {1 - p.x, 2 - p.y};
    return {std::clamp(p.x, 0.0f, 1.0f), std::clamp(p.y, 0.0f, 1.0f)};
}

}  // namespace photon
