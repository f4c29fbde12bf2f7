// Unit vectors packed into 32 bits by the octahedral map (Cigolle et al. 2014, "A Survey
// of Efficient Representations for Independent Unit Vectors", JCGT 3(2)); error below
// 1e-4 rad, which keeps per-pixel state small.
#pragma once
#include <cstdint>
#include <photon/vec.h>

namespace photon {

// The octahedral map itself: a unit vector to a point of [-1, 1]^2 and back.
inline Vec2 octahedralEncode(Vec3 v) {
    v = v / (std::abs(v.x) + std::abs(v.y) + std::abs(v.z));
    if (v.z >= 0) return {v.x, v.y};
    // fold the lower hemisphere over the diagonals
    return {(1 - std::abs(v.y)) * std::copysign(1.0f, v.x), (1 - std::abs(v.x)) * std::copysign(1.0f, v.y)};
}
inline Vec3 octahedralDecode(Vec2 e) {
    Vec3 v{e.x, e.y, 1 - std::abs(e.x) - std::abs(e.y)};
    if (v.z < 0) {
        float ox = v.x;
        v.x = (1 - std::abs(v.y)) * std::copysign(1.0f, ox);
        v.y = (1 - std::abs(ox)) * std::copysign(1.0f, v.y);
    }
    return normalize(v);
}

struct OctahedralVector {
    uint16_t x = 0, y = 0;

    OctahedralVector() = default;
    explicit OctahedralVector(Vec3 v) {
        Vec2 e = octahedralEncode(v);
        x = encode(e.x);
        y = encode(e.y);
    }
    Vec3 decode() const { return octahedralDecode({decode(x), decode(y)}); }

private:
    static uint16_t encode(float f) {
        // Round half up by truncation: the value is >= 0, and unlike lround this inlines.
        return static_cast<uint16_t>(std::clamp((f + 1) / 2, 0.0f, 1.0f) * 65535.0f + 0.5f);
    }
    static float decode(uint16_t u) { return -1 + 2 * (static_cast<float>(u) / 65535.0f); }
};

}  // namespace photon
