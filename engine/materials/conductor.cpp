// Rough metal: GGX microfacet reflection (Walter et al. 2007), isotropic or anisotropic, with
// either Schlick's Fresnel from the tint F0 or the exact Fresnel of a complex index of
// refraction eta + i k (pbrt-v4's ConductorBxDF). Smooth enough in both directions, it
// becomes an ideal mirror with the same Fresnel.
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"

namespace photon {
namespace {

// The lobe's GGX distribution. A lobe that is not smooth keeps each alpha at kSmoothAlpha or
// more, so that a very narrow direction of an anisotropic lobe stays within float range
// (pbrt-v4's TrowbridgeReitzDistribution does the same).
GGX microfacetDistribution(GgxAlpha alpha) {
    GGX ggx(alpha.x, alpha.y);
    if (ggx.smooth()) return ggx;
    return GGX(std::max(alpha.x, kSmoothAlpha), std::max(alpha.y, kSmoothAlpha));
}

class Conductor final : public Material {
public:
    Conductor(ColorParam reflectance, std::optional<ComplexIorParam> ior, GgxAlpha alpha)
        : Material(std::move(reflectance)), ior_(std::move(ior)), ggx_(microfacetDistribution(alpha)) {}

    unsigned lobes() const override { return ggx_.smooth() ? kDeltaLobe : kGlossyLobe; }
    bool textured() const override {
        return Material::textured() || (ior_ && (ior_->eta.textured() || ior_->k.textured()));
    }

    // f = F(wo.h) D G2 / (4 cos_o cos_i), Torrance-Sparrow with the height-correlated
    // Smith G2 (see microfacet.h). Zero unless wo and wi are both above the surface.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        if (ggx_.smooth() || !(lobes & kGlossyLobe)) return Color(0.0f);
        auto h = reflectionHalfVector(wo, wi);
        if (!h) return Color(0.0f);
        return fresnel(dot(wo, *h), in) * ggx_.reflectionNoFresnel(wo, wi, *h);
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs&, unsigned lobes) const override {
        if (ggx_.smooth() || !(lobes & kGlossyLobe)) return 0;
        auto h = reflectionHalfVector(wo, wi);
        return h ? ggx_.reflectionPdf(wo, *h) : 0.0f;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (wo.z <= 0 || !(lobes & this->lobes())) return std::nullopt;
        if (ggx_.smooth()) return sampleMirror(wo, in);
        // Visible normals never face away from wo, so only the reflected wi that ends up
        // below the horizon is lost (that energy is what single scattering misses).
        Vec3 wi = reflect(wo, ggx_.sampleVisibleNormal(wo, u));
        // Weighted through eval()/pdf(); the weight reduces analytically to F G2 / G1(wo)
        // (Heitz 2018).
        return weightedSample(wo, wi, in, mode, lobes);
    }

private:
    // Fresnel reflectance of a microfacet seen at cos(theta) = wo.h. Textured indices are
    // kept physical texel by texel: eta > 0 (at least kMinEta), k >= 0.
    Color fresnel(float cosTheta, const MaterialInputs& in) const {
        if (!ior_) return fresnelSchlick(in.tint, cosTheta);
        Color eta = vmax(ior_->eta.eval(in.uv), Color(kMinEta)), k = vmax(ior_->k.eval(in.uv), Color(0.0f));
        return fresnelConductor(cosTheta, eta, k);
    }

    // The alpha -> 0 limit of the microfacet lobe: all microfacets face n, so h = n,
    // G = 1 and the reflectance is the Fresnel term at the incidence angle.
    BSDFSample sampleMirror(Vec3 wo, const MaterialInputs& in) const {
        BSDFSample s;
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = fresnel(wo.z, in);
        s.pdf = 1;
        s.delta = true;
        return s;
    }

    static constexpr float kMinEta = 1e-3f;
    std::optional<ComplexIorParam> ior_;  // none: Schlick's Fresnel from the tint
    GGX ggx_;
};

}  // namespace

MaterialPtr makeConductor(ColorParam reflectance, float roughness) {
    float alpha = roughnessToAlpha(roughness);
    return makeConductor(std::move(reflectance), GgxAlpha{alpha, alpha});
}

MaterialPtr makeConductor(ColorParam reflectance, GgxAlpha alpha) {
    return std::make_shared<Conductor>(std::move(reflectance), std::nullopt, alpha);
}

MaterialPtr makeConductor(ComplexIor ior, GgxAlpha alpha) {
    return makeConductor(ComplexIorParam{ior.eta, ior.k}, alpha);
}

MaterialPtr makeConductor(ComplexIorParam ior, GgxAlpha alpha) {
    return std::make_shared<Conductor>(ColorParam(Color(1.0f)), std::move(ior), alpha);
}

}  // namespace photon
