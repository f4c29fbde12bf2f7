// The GGX (Trowbridge-Reitz) microfacet distribution shared by the conductor and the plastic
// coating: normal distribution, Smith masking and visible-normal sampling, anisotropic with
// roughnesses alphaX along the local frame's x axis and alphaY along its y axis (isotropic
// when equal). All vectors are in the local shading frame (z = macro normal).
#pragma once
#include <cmath>
#include <optional>
#include <photon/vec.h>

namespace photon {

// Below this alpha the lobe is narrower than float precision handles gracefully
// (D ~ 1/(pi alpha^2) explodes), so materials switch to an exact delta reflection.
constexpr float kSmoothAlpha = 1e-4f;

// photon's `roughness`: perceptually linear roughness to GGX alpha = roughness^2 (Burley
// 2012, "Physically-Based Shading at Disney", sec. 5.4).
inline float roughnessToAlpha(float roughness) { return roughness * roughness; }

// pbrt-v4's `remaproughness` (on by default in its conductor and dielectric), for scenes
// written with pbrt's meaning of roughness: alpha = sqrt(roughness)
// (TrowbridgeReitzDistribution::RoughnessToAlpha, pbrt-v4 sec. 9.6.1). Without the remap
// pbrt takes the roughness as alpha itself.
inline float pbrtRoughnessToAlpha(float roughness) { return std::sqrt(roughness); }

// What every microfacet distribution derives from its own D(h) and Smith Lambda(w)
// (Heitz 2014): masking, masking-shadowing and the reflection lobe. Distribution is the
// derived type (GGX below, Beckmann in beckmann.h), which supplies D and lambda.
template <class Distribution>
struct MicrofacetLobe {
    float alphaX, alphaY;

    MicrofacetLobe(float alphaX_, float alphaY_) : alphaX(alphaX_), alphaY(alphaY_) {}

    // Narrower than kSmoothAlpha in both directions: materials use a delta reflection.
    bool smooth() const { return std::max(alphaX, alphaY) < kSmoothAlpha; }

    // Smith masking of one direction, 1 / (1 + Lambda) (Smith 1967; Heitz 2014).
    float G1(Vec3 w) const { return 1.0f / (1.0f + self().lambda(w)); }

    // Height-correlated masking-shadowing 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014,
    // eq. 99): more accurate than the separable G1(wo) G1(wi), which double-counts
    // occlusion, and still symmetric in wo and wi, so the BRDF stays reciprocal.
    float G2(Vec3 wo, Vec3 wi) const { return 1.0f / (1.0f + self().lambda(wo) + self().lambda(wi)); }

    // Torrance-Sparrow reflection without Fresnel, D G2 / (4 cos_o cos_i) (Walter et al.
    // 2007, eq. 20); callers multiply by their own Fresnel term F(wo.h).
    float reflectionNoFresnel(Vec3 wo, Vec3 wi, Vec3 h) const {
        return self().D(h) * G2(wo, wi) / (4.0f * wo.z * wi.z);
    }

private:
    const Distribution& self() const { return static_cast<const Distribution&>(*this); }
};

// Both alphas must be positive; materials switch to a delta lobe below kSmoothAlpha.
struct GGX : MicrofacetLobe<GGX> {
    explicit GGX(float alpha) : MicrofacetLobe(alpha, alpha) {}
    GGX(float alphaX_, float alphaY_) : MicrofacetLobe(alphaX_, alphaY_) {}

    // Anisotropic D(h) = 1 / (pi ax ay (h.x^2/ax^2 + h.y^2/ay^2 + h.z^2)^2) (Heitz 2014,
    // "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 85),
    // multiplied through by ax ay: ax ay / (pi (h.x^2 ay/ax + h.y^2 ax/ay + ax ay h.z^2)^2).
    // For ax = ay = alpha that is Walter et al. 2007, eq. 33, with (n.h)^2 (alpha^2 - 1) + 1
    // written as h.x^2 + h.y^2 + alpha^2 h.z^2: the same for unit h but free of the
    // cancellation in alpha^2 - 1 when alpha is tiny.
    float D(Vec3 h) const {
        if (h.z <= 0) return 0;
        float axy = alphaX * alphaY;
        float denom = h.x * h.x * (alphaY / alphaX) + h.y * h.y * (alphaX / alphaY) + axy * h.z * h.z;
        return axy / (kPi * denom * denom);
    }

    // Smith Lambda for GGX: (sqrt(1 + alpha(w)^2 tan^2 theta) - 1) / 2, where the
    // anisotropic alpha(w)^2 = ax^2 cos^2 phi + ay^2 sin^2 phi (Heitz 2014, eqs. 80 and 86),
    // so alpha(w)^2 tan^2 theta = ax^2 (w.x^2 + (ay/ax)^2 w.y^2) / w.z^2 (written so that
    // the isotropic case rounds exactly as alpha^2 (w.x^2 + w.y^2) / w.z^2 does).
    float lambda(Vec3 w) const {
        float z2 = w.z * w.z;
        if (z2 == 0) return INFINITY;
        float ratio2 = (alphaY * alphaY) / (alphaX * alphaX);
        float alpha2Tan2 = alphaX * alphaX * (w.x * w.x + ratio2 * w.y * w.y) / z2;
        return 0.5f * (std::sqrt(1.0f + alpha2Tan2) - 1.0f);
    }

    // Samples a normal from the distribution of normals visible from wo (wo.z > 0),
    // D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z. Heitz 2018, "Sampling the GGX
    // Distribution of Visible Normals", JCGT 7(4), listing 1, which is anisotropic as
    // written: stretch wo by (ax, ay, 1) to the hemisphere configuration, sample the
    // projected disk, unstretch the normal by the same factors.
    Vec3 sampleVisibleNormal(Vec3 wo, Vec2 u) const {
        Vec3 vh = normalize(Vec3(alphaX * wo.x, alphaY * wo.y, wo.z));
        float lensq = vh.x * vh.x + vh.y * vh.y;
        Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
        Vec3 t2 = cross(vh, t1);
        float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
        float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
        // Warp the disk so its lower part matches the projection of the hemisphere's rim.
        float s = 0.5f * (1.0f + vh.z);
        p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
        Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
        return normalize(Vec3(alphaX * nh.x, alphaY * nh.y, std::max(0.0f, nh.z)));
    }

    // Density of wi = reflect(wo, h) under visible-normal sampling: D_wo(h) times the
    // reflection Jacobian 1 / (4 wo.h) (Walter et al. 2007, eq. 14), which cancels wo.h.
    float reflectionPdf(Vec3 wo, Vec3 h) const {
        if (wo.z <= 0 || dot(wo, h) <= 0) return 0;
        return G1(wo) * D(h) / (4.0f * wo.z);
    }

    // The conductor's sampling strategy: visible normals.
    Vec3 sampleHalfVector(Vec3 wo, Vec2 u) const { return sampleVisibleNormal(wo, u); }
};

// Half vector of a reflection pair in the upper hemisphere; nullopt when it is undefined
// (wo and wi not both above the surface, or opposite).
inline std::optional<Vec3> reflectionHalfVector(Vec3 wo, Vec3 wi) {
    if (wo.z <= 0 || wi.z <= 0) return std::nullopt;
    Vec3 h = wo + wi;
    float len2 = lengthSquared(h);
    if (len2 == 0) return std::nullopt;
    return h / std::sqrt(len2);
}

}  // namespace photon
