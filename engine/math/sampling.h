// Sampling warps shared by materials, lights and cameras (pbrt-v4 ch. A.5 and 4.x).
#pragma once
#include <optional>
#include "math/lanes.h"
#include <photon/vec.h>

namespace photon {

// sin and cos of |a| <= pi/4 by their Taylor series to a^9 and a^10: the truncation error
// is below (pi/4)^11/11! < 2e-9, under float rounding, at a fraction of sincosf's cost
// (every photon bounce and emission samples a disc). F: float or FloatLanes.
template <class F>
PHOTON_LANES_INLINE void cosSinQuarterTurn(F a, F& c, F& s) {
    F a2 = a * a;
    s = a * (1 + a2 * (-1.0f / 6 + a2 * (1.0f / 120 + a2 * (-1.0f / 5040 + a2 * (1.0f / 362880)))));
    c = 1 + a2 * (-0.5f + a2 * (1.0f / 24 + a2 * (-1.0f / 720 + a2 * (1.0f / 40320 - a2 * (1.0f / 3628800)))));
}

// Shirley & Chiu 1997 concentric map of [0,1)^2 to the unit disc: low distortion, keeps
// stratification. With the larger of |ox|, |oy| as the radius, the angle is pi/4 (oy/ox)
// or pi/2 - pi/4 (ox/oy); the second's cos and sin are the sin and cos of pi/4 (ox/oy),
// so both need the trigonometry of a quarter turn only. Written with selects, not
// branches, so that the photon walk's lanes share it.
template <class F>
PHOTON_LANES_INLINE void concentricDisk(F ux, F uy, F& dx, F& dy) {
    F ox = 2.0f * ux - 1.0f, oy = 2.0f * uy - 1.0f;
    auto xMajor = absValue(ox) > absValue(oy);
    F major = select(xMajor, ox, oy), minor = select(xMajor, oy, ox);
    // major is 0 only at the centre, where both are: the disc's centre, not 0 / 0.
    F safeMajor = select(major == 0.0f, broadcast<F>(1.0f), major);
    F c, s;
    cosSinQuarterTurn((kPi / 4.0f) * (minor / safeMajor), c, s);
    dx = major * select(xMajor, c, s);
    dy = major * select(xMajor, s, c);
}

inline Vec2 sampleUniformDiskConcentric(Vec2 u) {
    Vec2 d;
    concentricDisk(u.x, u.y, d.x, d.y);
    return d;
}

// Cosine-weighted hemisphere about +z (Malley's method); pdf = cos(theta)/pi.
template <class F>
PHOTON_LANES_INLINE void cosineHemisphere(F ux, F uy, F& x, F& y, F& z) {
    concentricDisk(ux, uy, x, y);
    z = safeSqrt(1.0f - x * x - y * y);
}
inline Vec3 sampleCosineHemisphere(Vec2 u) {
    Vec3 w;
    cosineHemisphere(u.x, u.y, w.x, w.y, w.z);
    return w;
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
// Written with selects: which half of the square u falls in is a coin toss, which a
// branch predictor gets wrong half the time (and photons are emitted millions of times).
template <class F>
PHOTON_LANES_INLINE void uniformTriangle(F ux, F uy, F& b0, F& b1) {
    auto lower = ux < uy;
    F halved = 0.5f * select(lower, ux, uy);
    b0 = select(lower, halved, ux - halved);
    b1 = select(lower, uy - halved, halved);
}
// The coordinates (b1, b2) of the point p0 + b1 e1 + b2 e2 of the triangle's plane nearest
// y; none for a degenerate triangle.
inline std::optional<Vec2> planeCoordinates(Vec3 y, Vec3 p0, Vec3 e1, Vec3 e2) {
    const Vec3 d = y - p0;
    const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), d1 = dot(d, e1), d2 = dot(d, e2);
    const float det = d11 * d22 - d12 * d12;
    if (!(det > 0)) return std::nullopt;
    return Vec2{(d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det};
}
inline Vec2 sampleUniformTriangle(Vec2 u) {
    Vec2 b;
    uniformTriangle(u.x, u.y, b.x, b.y);
    return b;
}

// Multiple importance sampling weight of a sample drawn with density pdfA, against another
// technique that could have drawn it with density pdfB: the power heuristic with exponent 2
// for one sample of each (Veach 1997, eq. 9.13).
inline float powerHeuristic(float pdfA, float pdfB) {
    const float a = pdfA * pdfA, b = pdfB * pdfB;
    return a + b > 0 ? a / (a + b) : 0.0f;
}

}  // namespace photon
