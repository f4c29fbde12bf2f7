// Normal and bump maps: the shading normal a map's texel, or a height field's slope, stands
// for.
#pragma once
#include "math/frame.h"
#include "texture/float_param.h"
#include "texture/texture.h"

namespace photon {

// How the surface point moves with its texture coordinates, dp/du and dp/dv (zero where the
// surface has no uv parameterisation that says, e.g. a mesh without uvs).
struct SurfaceTangents {
    Vec3 dpdu, dpdv;
};

// The step in uv over which a height field's slope is measured (pbrt-v4 sec. 10.5.2 uses
// the same when a ray carries no differentials).
constexpr float kBumpStep = 0.0005f;

// A normal on the geometric side of the surface, or n where it is not (it would let light
// through the surface).
inline Vec3 keptAbove(Vec3 bent, Vec3 n, Vec3 ng) {
    float len2 = lengthSquared(bent);
    if (!(len2 > 0)) return n;
    bent = bent / std::sqrt(len2);
    return dot(bent, ng) > 1e-3f ? bent : n;
}

// The normal of the surface displaced by height(at) along n (Blinn 1978; pbrt-v4 sec. 10.5.2,
// without the terms in dn/du, which are zero on flat triangles): dp/du' = dp/du + dh/du n,
// likewise in v, and n' = dp/du' x dp/dv', on n's side. Heights are in scene units. A step
// du moves the point by dp/du du as well, as pbrt-v4's BumpMap does, so that a height read
// at the point (a solid texture) has a slope too.
inline Vec3 bumpedNormal(const FloatParam& height, const TexturePoint& at, Vec3 n, Vec3 ng, const SurfaceTangents& t) {
    if (lengthSquared(t.dpdu) == 0 || lengthSquared(t.dpdv) == 0) return n;
    const Vec2 uv = at.uv;
    const float h = height.eval(at);
    const float dhdu = (height.eval({{uv.x + kBumpStep, uv.y}, at.p + t.dpdu * kBumpStep, at.n}) - h) / kBumpStep;
    const float dhdv = (height.eval({{uv.x, uv.y + kBumpStep}, at.p + t.dpdv * kBumpStep, at.n}) - h) / kBumpStep;
    Vec3 bent = cross(t.dpdu + n * dhdu, t.dpdv + n * dhdv);
    if (dot(bent, n) < 0) bent = -bent;
    return keptAbove(bent, n, ng);
}

// The map's value at `at`, RGB = (t + 1) / 2 for a unit vector t in the frame x = dp/du made
// perpendicular to n, y = n x x, z = n (the common "OpenGL" convention; pbrt-v4 sec. 10.5.3
// builds the same frame). Without a usable dp/du any frame about n serves: a map that only
// tilts toward +z (a flat one) means the same in all of them. A result on or below the
// geometric surface (ng) would let light through it: n itself is kept then.
inline Vec3 mappedNormal(const Texture& map, const TexturePoint& at, Vec3 n, Vec3 ng, Vec3 dpdu) {
    Color c = map.lookup(at);
    Vec3 t(2.0f * c.x - 1.0f, 2.0f * c.y - 1.0f, 2.0f * c.z - 1.0f);
    Vec3 x = dpdu - n * dot(n, dpdu);
    float len2 = lengthSquared(x);
    x = len2 > 1e-20f ? x / std::sqrt(len2) : Frame::fromNormal(n).s;
    return keptAbove(x * t.x + cross(n, x) * t.y + n * t.z, n, ng);
}

}  // namespace photon
