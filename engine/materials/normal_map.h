// Tangent-space normal maps: the shading normal a map's texel stands for.
#pragma once
#include "math/frame.h"
#include "texture/texture.h"

namespace photon {

// The map's value at uv, RGB = (t + 1) / 2 for a unit vector t in the frame x = dp/du made
// perpendicular to n, y = n x x, z = n (the common "OpenGL" convention; pbrt-v4 sec. 10.5.3
// builds the same frame). Without a usable dp/du any frame about n serves: a map that only
// tilts toward +z (a flat one) means the same in all of them. A result on or below the
// geometric surface (ng) would let light through it: n itself is kept then.
inline Vec3 mappedNormal(const Texture& map, Vec2 uv, Vec3 n, Vec3 ng, Vec3 dpdu) {
    Color c = map.lookup(uv);
    Vec3 t(2.0f * c.x - 1.0f, 2.0f * c.y - 1.0f, 2.0f * c.z - 1.0f);
    Vec3 x = dpdu - n * dot(n, dpdu);
    float len2 = lengthSquared(x);
    x = len2 > 1e-20f ? x / std::sqrt(len2) : Frame::fromNormal(n).s;
    Vec3 bent = x * t.x + cross(n, x) * t.y + n * t.z;
    float bentLen2 = lengthSquared(bent);
    if (!(bentLen2 > 0)) return n;
    bent = bent / std::sqrt(bentLen2);
    return dot(bent, ng) > 1e-3f ? bent : n;
}

}  // namespace photon
