#include "texture/texture_mapping.h"
#include <algorithm>

namespace photon {

Vec2 TextureMapping::apply(const TexturePoint& at) const {
    if (kind == Kind::Uv) return uv.apply(at.uv);
    const Vec3 q = textureFromWorld.point(at.p);
    Vec2 st;
    switch (kind) {
        case Kind::Spherical: {
            const float r = length(q);
            const float theta = r > 0 ? std::acos(std::clamp(q.z / r, -1.0f, 1.0f)) : 0.0f;
            float phi = std::atan2(q.y, q.x);
            if (phi < 0) phi += 2 * kPi;
            st = {theta / kPi, phi / (2 * kPi)};
            break;
        }
        case Kind::Cylindrical: st = {(kPi + std::atan2(q.y, q.x)) / (2 * kPi), q.z}; break;
        case Kind::Planar: st = {dot(q, planarS), dot(q, planarT)}; break;
        case Kind::Uv: break;
    }
    return uv.apply(st);
}

}  // namespace photon
