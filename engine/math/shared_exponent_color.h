// A non-negative colour in 32 bits: three 8-bit mantissas sharing an 8-bit exponent (Ward's
// RGBE, "Real Pixels", Graphics Gems II, 1991), for what a pass leaves at every pixel of a
// large frame. Each mantissa is rounded up or down at random, with the probability that
// makes its expectation the channel's value (dithered rounding), so that sums over many
// passes carry no rounding bias: a pass's error is at most 1/127 of its largest channel, and
// averages away as noise far below a render's own.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <algorithm>
#include <photon/vec.h>

namespace photon {

class SharedExponentColor {
public:
    SharedExponentColor() = default;
    // c rounded with the uniform number u in [0, 1) (the same for the three channels, each
    // unbiased on its own); negative channels are taken as 0, colours below 2^-121 as 0, and
    // infinite or NaN ones, or ones of 2^125 or more, as infinity.
    static SharedExponentColor of(Color c, float u) {
        const float r = std::max(c[0], 0.0f), g = std::max(c[1], 0.0f), b = std::max(c[2], 0.0f);
        const float m = std::max(r, std::max(g, b));
        if (!(m <= kLargest)) return SharedExponentColor(kInfinite);
        int e;
        std::frexp(m, &e);  // m = f 2^e, f in [0.5, 1)
        if (e < kLeastExponent) return {};
        // Mantissas k = c 2^(8 - e): the largest in [128, 256); rounded up it may reach 256,
        // which the next exponent holds as 128.
        for (;; ++e) {
            const float scale = std::ldexp(1.0f, 8 - e);
            const uint32_t kr = round(r * scale, u), kg = round(g * scale, u), kb = round(b * scale, u);
            if (kr < 256 && kg < 256 && kb < 256)
                return SharedExponentColor(kr | kg << 8 | kb << 16 | static_cast<uint32_t>(e + kBias) << 24);
        }
    }
    Color color() const {
        const uint32_t e = bits_ >> 24;
        if (e == kInfinite >> 24) return Color(std::numeric_limits<float>::infinity());
        const float scale = std::ldexp(1.0f, static_cast<int>(e) - kBias - 8);
        return Color(static_cast<float>(bits_ & 0xff) * scale, static_cast<float>(bits_ >> 8 & 0xff) * scale,
                     static_cast<float>(bits_ >> 16 & 0xff) * scale);
    }

private:
    explicit SharedExponentColor(uint32_t bits) : bits_(bits) {}
    static uint32_t round(float x, float u) { return static_cast<uint32_t>(x + u); }
    // Exponents e (of m = f 2^e) in [kLeastExponent, 126] (125 and one more where rounding
    // carries) are stored as e + kBias in [8, 254]; 255 marks infinity.
    static constexpr int kBias = 128, kLeastExponent = -120;
    static constexpr float kLargest = 0x1.fffffep124f;
    static constexpr uint32_t kInfinite = 0xffu << 24;
    uint32_t bits_ = 0;
};

}  // namespace photon
