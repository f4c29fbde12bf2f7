// Plastic: a Lambertian base under a dielectric coating of index `ior`. The coating is
// a GGX microfacet reflector (or an ideal mirror when smooth); the base only receives
// what the coating transmits on the way in and on the way out.
#include "math/sampling.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"

namespace photon {
namespace {

class Plastic final : public Material {
public:
    Plastic(ColorParam albedo, float ior, float roughness)
        : Material(std::move(albedo)), ior_(ior), ggx_{roughnessToAlpha(roughness)} {}

    unsigned lobes() const override { return kDiffuseLobe | (smooth() ? kDeltaLobe : kGlossyLobe); }

    // f = F(wo.h) D G2 / (4 cos_o cos_i) + (1 - F(cos_o)) (1 - F(cos_i)) albedo / pi.
    // Both terms are symmetric in wo and wi, hence reciprocal. The base only gets what
    // the coat transmits on the way in and out, so its albedo is below 1 - F(cos_o)
    // while the coat's is about F (the idea behind the coupled diffuse term of Ashikhmin
    // & Shirley 2000, "An Anisotropic Phong BRDF Model", here with the exact dielectric
    // Fresnel and no renormalisation). Re-reflections inside the coat are ignored, which
    // loses a little energy; tests/test_bsdf.cpp checks the albedo never exceeds one.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        if (wo.z <= 0 || wi.z <= 0) return Color(0.0f);
        Color f(0.0f);
        if (lobes & kDiffuseLobe) f += diffuse(wo, wi, in.tint);
        if (!smooth() && (lobes & kGlossyLobe)) f += Color(specular(wo, wi));
        return f;
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        lobes &= this->lobes();
        if (wo.z <= 0 || wi.z <= 0 || !lobes) return 0;
        float pSpec = specularProbability(wo, in.tint, lobes);
        float p = (lobes & kDiffuseLobe) ? (1.0f - pSpec) * cosineHemispherePdf(wi.z) : 0.0f;
        if (!smooth() && (lobes & kGlossyLobe)) {
            auto h = reflectionHalfVector(wo, wi);
            if (h) p += pSpec * ggx_.reflectionPdf(wo, *h);
        }
        return p;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        lobes &= this->lobes();
        if (wo.z <= 0 || !lobes) return std::nullopt;
        float pSpec = specularProbability(wo, in.tint, lobes);
        bool pickSpecular = uLobe < pSpec;
        if (smooth() && pickSpecular) return sampleCoatMirror(wo, pSpec);
        Vec3 wi = pickSpecular ? reflect(wo, ggx_.sampleVisibleNormal(wo, u)) : sampleCosineHemisphere(u);
        // Both rough lobes could have produced wi, so the density is the full mixture
        // (one-sample MIS with the balance heuristic, Veach 1997 sec. 9.2.4).
        std::optional<BSDFSample> s = weightedSample(wo, wi, in, mode, lobes);
        if (!s) return std::nullopt;
        // Smooth coat: only the diffuse kind was picked here, with probability 1 - pSpec.
        s->lobeProbability = smooth() ? 1.0f - pSpec : 1.0f;
        return s;
    }

    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override { return 1.0f - specularProbability(wo, in.tint, kAllLobes); }

private:
    bool smooth() const { return ggx_.smooth(); }
    float fresnel(float cosTheta) const { return fresnelDielectric(cosTheta, ior_); }

    Color diffuse(Vec3 wo, Vec3 wi, Color albedo) const {
        return albedo * ((1.0f - fresnel(wo.z)) * (1.0f - fresnel(wi.z)) * kInvPi);
    }

    float specular(Vec3 wo, Vec3 wi) const {
        auto h = reflectionHalfVector(wo, wi);
        if (!h) return 0;
        return fresnel(dot(wo, *h)) * ggx_.reflectionNoFresnel(wo, wi, *h);
    }

    // Pick the coat in proportion to an estimate of each lobe's albedo: F(cos_o) for the
    // coat, (1 - F(cos_o)) max(albedo) for the base (max, not luminance, so a saturated
    // colour channel is not starved). Clamped so neither lobe is ever left unsampled,
    // which keeps the mixture pdf positive wherever f is (no bias) and bounds the weights.
    // With the coat or the base masked out, the other is always picked.
    float specularProbability(Vec3 wo, Color albedo, unsigned lobes) const {
        if (!(lobes & kDiffuseLobe)) return 1.0f;
        if (!(lobes & (kGlossyLobe | kDeltaLobe))) return 0.0f;
        float F = fresnel(wo.z);
        float base = (1.0f - F) * std::max(0.0f, maxComponent(albedo));
        float sum = F + base;
        float p = sum > 0 ? F / sum : 1.0f;
        return std::clamp(p, kMinLobeProbability, 1.0f - kMinLobeProbability);
    }

    // Smooth coat: the mirror direction carries F(cos_o); divided by its choice probability.
    BSDFSample sampleCoatMirror(Vec3 wo, float pSpec) const {
        BSDFSample s;
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = Color(fresnel(wo.z) / pSpec);
        s.pdf = pSpec;
        s.delta = true;
        s.lobeProbability = pSpec;
        return s;
    }

    static constexpr float kMinLobeProbability = 0.05f;
    float ior_;
    GGX ggx_;
};

}  // namespace

MaterialPtr makePlastic(ColorParam albedo, float ior, float roughness) {
    return std::make_shared<Plastic>(std::move(albedo), ior, roughness);
}

}  // namespace photon
