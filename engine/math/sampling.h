// Sampling warps shared by materials, lights and cameras (pbrt-v4 ch. A.5 and 4.x).
#pragma once
#include "vec.h"

namespace photon {

inline Vec2 sampleUniformDiskConcentric(Vec2 u) {
    // Shirley & Chiu 1997 concentric map: low distortion, keeps stratification.
    float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
    if (ox == 0 && oy == 0) return {0, 0};
    float r, theta;
    if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        theta = (kPi / 4.0f) * (oy / ox);
    } else {
        r = oy;
        theta = kPi / 2.0f - (kPi / 4.0f) * (ox / oy);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
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
