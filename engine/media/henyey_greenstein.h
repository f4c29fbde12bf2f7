// The Henyey-Greenstein phase function (Henyey & Greenstein 1941), with which a homogeneous
// medium (MediumDescription) turns the light it scatters. As in pbrt-v4 (11.3.1), wo and wi
// both point away from the scattering point: wo back toward where the path came from (the
// viewer), wi toward where the light comes from, so forward scattering (g > 0) favours
// wi = -wo.
#pragma once
#include <algorithm>
#include <cmath>
#include "math/frame.h"

namespace photon {

// p(wo, wi) per steradian, for cosTheta = dot(wo, wi); integrates to 1 over the sphere.
inline float henyeyGreenstein(float cosTheta, float g) {
    constexpr float kInv4Pi = 0.07957747154594767f;
    const float denom = 1 + g * g + 2 * g * cosTheta;
    return kInv4Pi * (1 - g * g) / (denom * std::sqrt(std::max(denom, 1e-12f)));
}

struct PhaseSample {
    Vec3 wi;
    float pdf;  // equal to the phase function: the sample's weight p / pdf is 1
};

// Draws wi with density p(wo, .) exactly, by inverting its cumulative distribution in
// cos theta (pbrt-v4's SampleHenyeyGreenstein; isotropic for |g| < 1e-3, where the
// inversion loses its precision).
inline PhaseSample sampleHenyeyGreenstein(Vec3 wo, float g, Vec2 u) {
    float cosTheta;
    if (std::abs(g) < 1e-3f) {
        cosTheta = 1 - 2 * u.x;
    } else {
        const float s = (1 - g * g) / (1 + g - 2 * g * u.x);
        cosTheta = -(1 + g * g - s * s) / (2 * g);
    }
    cosTheta = std::clamp(cosTheta, -1.0f, 1.0f);
    const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
    const float phi = 2 * 3.14159265358979f * u.y;
    const Vec3 local{sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
    const Vec3 wi = Frame::fromNormal(wo).toWorld(local);
    return {wi, henyeyGreenstein(cosTheta, g)};
}

}  // namespace photon
