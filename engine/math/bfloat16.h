// bfloat16: a float's upper 16 bits (its sign, 8-bit exponent and 7 bits of mantissa: 8
// significant bits, 0.4%), for per-pixel figures only statistics read, where a float's
// range matters and its precision does not.
#pragma once
#include <cstdint>
#include <cstring>

namespace photon {

// Rounded to the nearest, ties to even (no NaN is passed here: the figures are sums of squares).
inline uint16_t toBfloat16(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits += 0x7fffu + ((bits >> 16) & 1u);
    return static_cast<uint16_t>(bits >> 16);
}

inline float fromBfloat16(uint16_t b) {
    const uint32_t bits = static_cast<uint32_t>(b) << 16;
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

}  // namespace photon
