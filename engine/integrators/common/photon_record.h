// One stored photon in 20 bytes (Jensen 2001, sec. 5.3 stores 20 too): position as three
// floats, flux in a shared-exponent RGB word and the incoming direction in 16 bits.
//  - Flux: RGBE (Ward 1991) with round-to-nearest 8-bit mantissas: every channel is off
//    by at most half a step, max/256 of the largest channel (0.4%), and rounding errors
//    of neighbouring photons average out; that is far under the noise of an estimate
//    over k >= 50 photons (about 1/sqrt(k), 14%), and the 8-bit exponent covers any
//    flux a photon can carry.
//  - Direction: the octahedral map with 8 bits a coordinate: error below 1 degree (0.34
//    on average, measured over a million directions), like Jensen's two-byte theta/phi.
//    It only feeds BSDF evaluation at non-specular surfaces, whose lobes are far wider.
#pragma once
#include <cmath>
#include <cstdint>
#include "math/octahedral.h"
#include <photon/vec.h>

namespace photon {

struct StoredPhoton {
    // Set when the photon bounced off a non-specular surface before arriving here:
    // the global-map photons that are neither direct light nor caustics.
    static constexpr uint8_t kIndirect = 1;

    float p[3];
    uint32_t flux;
    uint16_t direction;
    uint8_t flags;
    uint8_t unused = 0;

    StoredPhoton() = default;
    StoredPhoton(Vec3 position, Vec3 wi, Color f, uint8_t flags_)
        : p{position.x, position.y, position.z}, flux(encodeFlux(f)), direction(encodeDirection(wi)), flags(flags_) {}

    Vec3 position() const { return {p[0], p[1], p[2]}; }
    Color power() const { return decodeFlux(flux); }
    Vec3 incoming() const {
        return octahedralDecode({(direction & 0xff) / 127.5f - 1.0f, (direction >> 8) / 127.5f - 1.0f});
    }

    static uint32_t encodeFlux(Color c) {
        float m = maxComponent(c);
        if (!(m > 1e-38f) || !std::isfinite(m)) return 0;
        int e;
        std::frexp(m, &e);  // m = f 2^e with f in [0.5, 1)
        auto mantissa = [&](float v) { return static_cast<uint32_t>(std::lround(std::ldexp(std::max(v, 0.0f), 8 - e))); };
        if (mantissa(m) > 255) ++e;  // rounding carried into the next power of two
        e = std::clamp(e, -127, 128);
        return mantissa(c.x) | mantissa(c.y) << 8 | mantissa(c.z) << 16 | static_cast<uint32_t>(e + 127) << 24;
    }
    static Color decodeFlux(uint32_t v) {
        if (v == 0) return Color(0.0f);
        int e = static_cast<int>(v >> 24) - 127;
        return Color(static_cast<float>(v & 0xff), static_cast<float>((v >> 8) & 0xff),
                     static_cast<float>((v >> 16) & 0xff)) * std::ldexp(1.0f, e - 8);
    }
    static uint16_t encodeDirection(Vec3 w) {
        Vec2 e = octahedralEncode(w);
        auto q = [](float f) { return static_cast<uint16_t>(std::lround(std::clamp((f + 1) * 127.5f, 0.0f, 255.0f))); };
        return static_cast<uint16_t>(q(e.x) | q(e.y) << 8);
    }
};
static_assert(sizeof(StoredPhoton) == 20, "photon records are 20 bytes");

}  // namespace photon
