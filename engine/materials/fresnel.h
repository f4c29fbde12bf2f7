// Fresnel reflectance and Snell refraction shared by the dielectric, conductor and
// plastic materials. Local-frame conventions: directions point away from the surface.
#pragma once
#include <optional>
#include "../math/vec.h"

namespace photon {

// Exact unpolarised Fresnel reflectance of a smooth dielectric boundary: the mean of
// the s- and p-polarised amplitudes squared (Hecht, "Optics", ch. 4; pbrt-v4 sec. 9.3).
// `eta` is n_inside / n_outside, the outside being the side the normal points to; a
// negative cosThetaI means the light arrives from inside, so the ratio is inverted.
// Returns 1 under total internal reflection.
inline float fresnelDielectric(float cosThetaI, float eta) {
    cosThetaI = std::clamp(cosThetaI, -1.0f, 1.0f);
    if (cosThetaI < 0) {
        eta = 1.0f / eta;
        cosThetaI = -cosThetaI;
    }
    float sin2ThetaI = std::max(0.0f, 1.0f - cosThetaI * cosThetaI);
    float sin2ThetaT = sin2ThetaI / (eta * eta);  // Snell: sin_t = sin_i / eta
    if (sin2ThetaT >= 1.0f) return 1.0f;
    float cosThetaT = std::sqrt(1.0f - sin2ThetaT);
    float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

// Schlick's approximation F0 + (1 - F0)(1 - cos)^5 (Schlick 1994, "An Inexpensive BRDF
// Model for Physically-based Rendering", eq. 15): the usual artist-friendly conductor
// model, where F0 is the colour at normal incidence.
inline Color fresnelSchlick(Color f0, float cosTheta) {
    float m = std::clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (Color(1.0f) - f0) * (m2 * m2 * m);
}

struct Refraction {
    Vec3 wt;     // transmitted direction, pointing away from the surface on the far side
    float etap;  // n_far / n_near: the relative index across the boundary along wt
};

// Refracts w (pointing away from the surface) through the boundary with normal n and
// relative index eta = n_inside / n_outside, n pointing outside (pbrt-v4 sec. 9.3,
// Snell's law in vector form). Works from either side; nullopt on total internal reflection.
inline std::optional<Refraction> refract(Vec3 w, Vec3 n, float eta) {
    float cosThetaI = dot(n, w);
    if (cosThetaI < 0) {
        eta = 1.0f / eta;
        cosThetaI = -cosThetaI;
        n = -n;
    }
    float sin2ThetaI = std::max(0.0f, 1.0f - cosThetaI * cosThetaI);
    float sin2ThetaT = sin2ThetaI / (eta * eta);
    if (sin2ThetaT >= 1.0f) return std::nullopt;
    float cosThetaT = std::sqrt(1.0f - sin2ThetaT);
    return Refraction{-w / eta + (cosThetaI / eta - cosThetaT) * n, eta};
}

}  // namespace photon
