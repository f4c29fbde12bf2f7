// Fresnel reflectance and Snell refraction shared by the dielectric, conductor and
// plastic materials. Local-frame conventions: directions point away from the surface.
#pragma once
#include <complex>
#include <optional>
#include "math/lanes.h"
#include <photon/vec.h>

namespace photon {

// Exact unpolarised Fresnel reflectance of a smooth dielectric boundary: the mean of
// the s- and p-polarised amplitudes squared (Hecht, "Optics", ch. 4; pbrt-v4 sec. 9.3).
// `eta` is n_inside / n_outside, the outside being the side the normal points to; a
// negative cosThetaI means the light arrives from inside, so the ratio is inverted.
// Returns 1 under total internal reflection. F is a float or lanes of them (math/lanes.h):
// one formula for both, written with selects.
template <class F>
PHOTON_LANES_INLINE F fresnelDielectric(F cosThetaI, F eta) {
    cosThetaI = select(cosThetaI < -1.0f, broadcast<F>(-1.0f), select(1.0f < cosThetaI, broadcast<F>(1.0f), cosThetaI));
    auto inside = cosThetaI < 0.0f;
    eta = select(inside, 1.0f / eta, eta);
    cosThetaI = select(inside, -cosThetaI, cosThetaI);
    F sin2ThetaI = 1.0f - cosThetaI * cosThetaI;
    sin2ThetaI = select(0.0f < sin2ThetaI, sin2ThetaI, broadcast<F>(0.0f));
    F sin2ThetaT = sin2ThetaI / (eta * eta);  // Snell: sin_t = sin_i / eta
    F cosThetaT = safeSqrt(1.0f - sin2ThetaT);
    F rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    F rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return select(sin2ThetaT >= 1.0f, broadcast<F>(1.0f),
                  0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular));
}

// Schlick's approximation F0 + (1 - F0)(1 - cos)^5 (Schlick 1994, "An Inexpensive BRDF
// Model for Physically-based Rendering", eq. 15): the usual artist-friendly conductor
// model, where F0 is the colour at normal incidence.
inline Color fresnelSchlick(Color f0, float cosTheta) {
    float m = std::clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (Color(1.0f) - f0) * (m2 * m2 * m);
}

// Exact unpolarised Fresnel reflectance of a smooth conductor of complex index eta + i k
// (k the extinction coefficient), light arriving from a medium of index 1: Fresnel's
// equations with a complex index, the mean of |r_parallel|^2 and |r_perpendicular|^2 (Hecht,
// "Optics", sec. 4.8; pbrt-v4 sec. 9.3.6, FrComplex). The transmitted cosine is complex too,
// cos_t = sqrt(1 - sin^2_i / (eta + i k)^2). cosThetaI is clamped to [0, 1]: conductors are
// opaque, so light only ever arrives from outside. With k = 0 this is fresnelDielectric from
// outside; at normal incidence it is ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2); at grazing
// incidence it tends to 1.
inline float fresnelConductor(float cosThetaI, float eta, float k) {
    using Complex = std::complex<float>;
    cosThetaI = std::clamp(cosThetaI, 0.0f, 1.0f);
    Complex index(eta, k);
    float sin2ThetaI = 1.0f - cosThetaI * cosThetaI;
    Complex sin2ThetaT = sin2ThetaI / (index * index);
    Complex cosThetaT = std::sqrt(1.0f - sin2ThetaT);
    Complex rParallel = (index * cosThetaI - cosThetaT) / (index * cosThetaI + cosThetaT);
    Complex rPerpendicular = (cosThetaI - index * cosThetaT) / (cosThetaI + index * cosThetaT);
    return 0.5f * (std::norm(rParallel) + std::norm(rPerpendicular));
}

// The same per colour channel, for RGB eta and k (materials/metal_table.h).
inline Color fresnelConductor(float cosThetaI, Color eta, Color k) {
    return {fresnelConductor(cosThetaI, eta.x, k.x), fresnelConductor(cosThetaI, eta.y, k.y),
            fresnelConductor(cosThetaI, eta.z, k.z)};
}

struct Refraction {
    Vec3 wt;     // transmitted direction, pointing away from the surface on the far side
    float etap;  // n_far / n_near: the relative index across the boundary along wt
};

// Refracts w (pointing away from the surface) through the boundary with normal n and
// relative index eta = n_inside / n_outside, n pointing outside (pbrt-v4 sec. 9.3,
// Snell's law in vector form). Works from either side. Component by component, for a
// float or lanes of them: writes the transmitted direction t and etap, and returns where
// the light is totally reflected instead (t is then not a direction).
template <class F>
PHOTON_LANES_INLINE auto refractComponents(F wx, F wy, F wz, F nx, F ny, F nz, F eta, F& tx, F& ty, F& tz, F& etap) {
    F cosThetaI = nx * wx + ny * wy + nz * wz;
    auto flip = cosThetaI < 0.0f;
    eta = select(flip, 1.0f / eta, eta);
    cosThetaI = select(flip, -cosThetaI, cosThetaI);
    nx = select(flip, -nx, nx);
    ny = select(flip, -ny, ny);
    nz = select(flip, -nz, nz);
    F sin2ThetaI = 1.0f - cosThetaI * cosThetaI;
    sin2ThetaI = select(0.0f < sin2ThetaI, sin2ThetaI, broadcast<F>(0.0f));
    F sin2ThetaT = sin2ThetaI / (eta * eta);
    F cosThetaT = safeSqrt(1.0f - sin2ThetaT);
    // -w / eta + (cos_i / eta - cos_t) n, with Vec3's division by a scalar (times 1/eta).
    F inverseEta = 1.0f / eta, along = cosThetaI / eta - cosThetaT;
    tx = -wx * inverseEta + along * nx;
    ty = -wy * inverseEta + along * ny;
    tz = -wz * inverseEta + along * nz;
    etap = eta;
    return sin2ThetaT >= 1.0f;
}

// The same for one direction; nullopt on total internal reflection.
inline std::optional<Refraction> refract(Vec3 w, Vec3 n, float eta) {
    Refraction r;
    if (refractComponents(w.x, w.y, w.z, n.x, n.y, n.z, eta, r.wt.x, r.wt.y, r.wt.z, r.etap)) return std::nullopt;
    return r;
}

}  // namespace photon
