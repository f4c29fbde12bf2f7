// Where on its pattern a texture is read for a surface point (pbrt-v4's TextureMapping2D):
// at the surface's own uv, or at coordinates of the point in the texture's space.
#pragma once
#include <cmath>
#include "math/transform.h"
#include "texture/texture.h"

namespace photon {

// uv -> uv * scale, turned counter-clockwise by `rotation` (radians; v up), + offset, then
// the texture (pbrt-v4's UVMapping: su, sv, du, dv; glTF's KHR_texture_transform: T R S).
struct UvMapping {
    Vec2 scale{1, 1}, offset{0, 0};
    float rotation = 0;
    Vec2 apply(Vec2 uv) const {
        const Vec2 s{uv.x * scale.x, uv.y * scale.y};
        if (rotation == 0) return {s.x + offset.x, s.y + offset.y};
        const float c = std::cos(rotation), n = std::sin(rotation);
        return {c * s.x - n * s.y + offset.x, n * s.x + c * s.y + offset.y};
    }
    bool identity() const { return scale.x == 1 && scale.y == 1 && offset.x == 0 && offset.y == 0 && rotation == 0; }
};

// The (s, t) a 2D texture is read at: from the surface's uv, or from the point q =
// textureFromWorld(p) in the texture's own space, as pbrt-v4 maps them (its SphericalMapping,
// CylindricalMapping, PlanarMapping; the texture's space is where the scene placed it):
//  - spherical: s = theta / pi, t = phi / 2pi of the direction from the origin to q
//    (theta from +z, phi about z from +x, in [0, 2pi));
//  - cylindrical: s = (pi + atan2(q.y, q.x)) / 2pi, t = q.z;
//  - planar: s = q . planarS, t = q . planarT.
// Then `uv` scales, turns and offsets the result (pbrt-v4's planar udelta and vdelta are its
// offset).
struct TextureMapping {
    enum class Kind { Uv, Spherical, Cylindrical, Planar };
    Kind kind = Kind::Uv;
    Transform textureFromWorld;
    Vec3 planarS{1, 0, 0}, planarT{0, 1, 0};
    UvMapping uv;

    TextureMapping() = default;
    TextureMapping(UvMapping m) : uv(m) {}  // NOLINT: a uv mapping is one of these

    Vec2 apply(const TexturePoint& at) const;
    bool identity() const { return kind == Kind::Uv && uv.identity(); }
};

}  // namespace photon
