// The isotropic GGX (Trowbridge-Reitz) microfacet distribution shared by the conductor
// and the plastic coating: normal distribution, Smith masking and visible-normal sampling.
// All vectors are in the local shading frame (z = macro normal).
#pragma once
#include <optional>
#include <photon/vec.h>

namespace photon {

// Below this alpha the lobe is narrower than float precision handles gracefully
// (D ~ 1/(pi alpha^2) explodes), so materials switch to an exact delta reflection.
constexpr float kSmoothAlpha = 1e-4f;

// Perceptually linear roughness to GGX alpha (Burley 2012, "Physically-Based Shading
// at Disney", sec. 5.4).
inline float roughnessToAlpha(float roughness) { return roughness * roughness; }

struct GGX {
    float alpha;

    // D(h) = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2) (Walter et al. 2007, eq. 33),
    // with the bracket rewritten as h.x^2 + h.y^2 + alpha^2 h.z^2: the same for unit h
    // but free of the cancellation in alpha^2 - 1 when alpha is tiny.
    float D(Vec3 h) const {
        if (h.z <= 0) return 0;
        float a2 = alpha * alpha;
        float denom = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
        return a2 / (kPi * denom * denom);
    }

    // Smith Lambda for GGX: (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2 (Heitz 2014,
    // "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 86).
    float lambda(Vec3 w) const {
        float z2 = w.z * w.z;
        if (z2 == 0) return INFINITY;
        float alpha2Tan2 = alpha * alpha * (w.x * w.x + w.y * w.y) / z2;
        return 0.5f * (std::sqrt(1.0f + alpha2Tan2) - 1.0f);
    }

    // Smith masking of one direction, 1 / (1 + Lambda) (Smith 1967; Heitz 2014).
    float G1(Vec3 w) const { return 1.0f / (1.0f + lambda(w)); }

    // Height-correlated masking-shadowing 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014,
    // eq. 99): more accurate than the separable G1(wo) G1(wi), which double-counts
    // occlusion, and still symmetric in wo and wi, so the BRDF stays reciprocal.
    float G2(Vec3 wo, Vec3 wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

    // Samples a normal from the distribution of normals visible from wo (wo.z > 0),
    // D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z. Heitz 2018, "Sampling the GGX
    // Distribution of Visible Normals", JCGT 7(4), listing 1: stretch wo to the
    // hemisphere configuration, sample the projected disk, unstretch.
    Vec3 sampleVisibleNormal(Vec3 wo, Vec2 u) const {
        Vec3 vh = normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
        float lensq = vh.x * vh.x + vh.y * vh.y;
        Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
        Vec3 t2 = cross(vh, t1);
        float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
        float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
        // Warp the disk so its lower part matches the projection of the hemisphere's rim.
        float s = 0.5f * (1.0f + vh.z);
        p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
        Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
        return normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
    }

    // Density of wi = reflect(wo, h) under visible-normal sampling: D_wo(h) times the
    // reflection Jacobian 1 / (4 wo.h) (Walter et al. 2007, eq. 14), which cancels wo.h.
    float reflectionPdf(Vec3 wo, Vec3 h) const {
        if (wo.z <= 0 || dot(wo, h) <= 0) return 0;
        return G1(wo) * D(h) / (4.0f * wo.z);
    }

    // Torrance-Sparrow reflection without Fresnel, D G2 / (4 cos_o cos_i) (Walter et al.
    // 2007, eq. 20); callers multiply by their own Fresnel term F(wo.h).
    float reflectionNoFresnel(Vec3 wo, Vec3 wi, Vec3 h) const {
        return D(h) * G2(wo, wi) / (4.0f * wo.z * wi.z);
    }
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
