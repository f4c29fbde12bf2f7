#include "materials/coat_over_diffuse.h"
#include "math/sampling.h"

namespace photon {

// f = coat specular + the model's diffuse term. Both are symmetric in wo and wi, hence
// reciprocal.
Color CoatOverDiffuse::eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const {
    if (wo.z <= 0 || wi.z <= 0) return Color(0.0f);
    Color f(0.0f);
    if (lobes & kDiffuseLobe) f += diffuse(wo, wi, in.tint);
    if (!smooth() && (lobes & kGlossyLobe)) f += Color(specular(wo, wi));
    return f;
}

float CoatOverDiffuse::pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const {
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

std::optional<BSDFSample> CoatOverDiffuse::sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in,
                                                  TransportMode mode, unsigned lobes) const {
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

float CoatOverDiffuse::specular(Vec3 wo, Vec3 wi) const {
    auto h = reflectionHalfVector(wo, wi);
    if (!h) return 0;
    return fresnel(dot(wo, *h)) * ggx_.reflectionNoFresnel(wo, wi, *h);
}

// Pick the coat in proportion to an estimate of each lobe's albedo: the coat's own, and
// (1 - coat) max(albedo) for the base (max, not luminance, so a saturated colour channel
// is not starved). Clamped so neither lobe is ever left unsampled, which keeps the mixture
// pdf positive wherever f is (no bias) and bounds the weights. With the coat or the base
// masked out, the other is always picked.
float CoatOverDiffuse::specularProbability(Vec3 wo, Color albedo, unsigned lobes) const {
    if (!(lobes & kDiffuseLobe)) return 1.0f;
    if (!(lobes & (kGlossyLobe | kDeltaLobe))) return 0.0f;
    float coat = coatAlbedo(wo.z);
    float base = (1.0f - coat) * std::max(0.0f, maxComponent(albedo));
    float sum = coat + base;
    float p = sum > 0 ? coat / sum : 1.0f;
    return std::clamp(p, kMinLobeProbability, 1.0f - kMinLobeProbability);
}

// Smooth coat: the mirror direction carries F(cos_o); divided by its choice probability.
BSDFSample CoatOverDiffuse::sampleCoatMirror(Vec3 wo, float pSpec) const {
    BSDFSample s;
    s.wi = Vec3(-wo.x, -wo.y, wo.z);
    s.weight = Color(fresnel(wo.z) / pSpec);
    s.pdf = pSpec;
    s.delta = true;
    s.lobeProbability = pSpec;
    return s;
}

}  // namespace photon
