// Sampling warps shared by materials, lights and cameras (pbrt-v4 ch. A.5 and 4.x).
#pragma once
#include "vec.h"

namespace photon {

// sin and cos of |a| <= pi/4 by their Taylor series to a^9 and a^10: the truncation error
// is below (pi/4)^11/11! < 2e-9, under float rounding, at a fraction of sincosf's cost
// (every photon bounce and emission samples a disc).
inline Vec2 cosSinQuarterTurn(float a) {
    float a2 = a * a;
    float s = a * (1 + a2 * (-1.0f / 6 + a2 * (1.0f / 120 + a2 * (-1.0f / 5040 + a2 * (1.0f / 362880)))));
    float c = 1 + a2 * (-0.5f + a2 * (1.0f / 24 + a2 * (-1.0f / 720 + a2 * (1.0f / 40320 - a2 * (1.0f / 3628800)))));
    return {c, s};
}

inline Vec2 sampleUniformDiskConcentric(Vec2 u) {
    // Shirley & Chiu 1997 concentric map: low distortion, keeps stratification. The angle
    // is pi/4 * (oy/ox) or pi/2 - pi/4 * (ox/oy); the second's cos and sin are the sin and
    // cos of pi/4 * (ox/oy), so both need the trigonometry of a quarter turn only.
    float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
    if (ox == 0 && oy == 0) return {0, 0};
    if (std::abs(ox) > std::abs(oy)) {
        Vec2 cs = cosSinQuarterTurn((kPi / 4.0f) * (oy / ox));
        return {ox * cs.x, ox * cs.y};
    }
    Vec2 cs = cosSinQuarterTurn((kPi / 4.0f) * (ox / oy));
    return {oy * cs.y, oy * cs.x};
}

// Cosine-weighted hemisphere about +z (Malley's method); pdf = cos(theta)/pi.
inline Vec3 sampleCosineHemisphere(Vec2 u) {
    Vec2 d = sampleUniformDiskConcentric(u);
    float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}
inline float cosineHemispherePdf(float cosTheta) { return cosTheta * kInvPi; }

// Uniform direction on the unit sphere; pdf = 1/(4 pi).
inline Vec3 sampleUniformSphere(Vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPi);

// Uniform direction in the cone of directions within acos(cosMax) of +z; pdf = 1/(2 pi (1-cosMax)).
inline Vec3 sampleUniformCone(Vec2 u, float cosMax) {
    float cosTheta = (1.0f - u.x) + u.x * cosMax;
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u.y;
    return {std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta};
}
inline float uniformConePdf(float cosMax) { return 1.0f / (2.0f * kPi * (1.0f - cosMax)); }

// Uniform point on a triangle as barycentrics (b0, b1); Heitz 2019's low-distortion map.
inline Vec2 sampleUniformTriangle(Vec2 u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2;
        b0 = u.x - b1;
    }
    return {b0, b1};
}

}  // namespace photon
