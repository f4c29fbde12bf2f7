// Rough metal: GGX or Beckmann microfacet reflection (Walter et al. 2007), isotropic or
// anisotropic, with
// either Schlick's Fresnel from the tint F0 or the exact Fresnel of a complex index of
// refraction eta + i k (pbrt-v4's ConductorBxDF). Index and roughness may be textured.
// Smooth enough in both directions (and not textured), it becomes an ideal mirror with the
// same Fresnel.
#include "materials/beckmann.h"
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"

namespace photon {
namespace {

// GGX alpha of a roughness value under the scene's meaning of roughness (material.h).
float alphaOf(float roughness, RoughnessToAlpha toAlpha) {
    switch (toAlpha) {
        case RoughnessToAlpha::Square: return roughnessToAlpha(roughness);
        case RoughnessToAlpha::SquareRoot: return pbrtRoughnessToAlpha(roughness);
        case RoughnessToAlpha::Identity: break;
    }
    return roughness;
}

// The lobe's distribution for alphas ax, ay. A lobe that is not smooth keeps each alpha at
// kSmoothAlpha or more, so that a very narrow direction of an anisotropic lobe stays within
// float range (pbrt-v4's TrowbridgeReitzDistribution does the same).
template <class Distribution>
Distribution lobeDistribution(float ax, float ay) {
    Distribution d(ax, ay);
    if (d.smooth()) return d;
    return Distribution(std::max(ax, kSmoothAlpha), std::max(ay, kSmoothAlpha));
}

// Distribution: GGX or Beckmann.
template <class Distribution>
class Conductor final : public Material {
public:
    Conductor(ColorParam reflectance, std::optional<ComplexIorParam> ior, MicrofacetRoughness roughness)
        : Material(std::move(reflectance)),
          ior_(std::move(ior)),
          roughness_(std::move(roughness)),
          texturedRoughness_(roughness_.u.textured() || roughness_.v.textured()),
          lobe_(lobeDistribution<Distribution>(alphaOf(roughness_.u.value, roughness_.toAlpha),
                                               alphaOf(roughness_.v.value, roughness_.toAlpha))) {}

    unsigned lobes() const override { return smooth() ? kDeltaLobe : kGlossyLobe; }
    bool textured() const override {
        return Material::textured() || texturedRoughness_ || (ior_ && (ior_->eta.textured() || ior_->k.textured()));
    }

    // f = F(wo.h) D G2 / (4 cos_o cos_i), Torrance-Sparrow with the height-correlated
    // Smith G2 (see microfacet.h). Zero unless wo and wi are both above the surface.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        if (smooth() || !(lobes & kGlossyLobe)) return Color(0.0f);
        auto h = reflectionHalfVector(wo, wi);
        if (!h) return Color(0.0f);
        return fresnel(dot(wo, *h), in) * lobeAt(in.at).reflectionNoFresnel(wo, wi, *h);
    }

    Color normalReflectance(const MaterialInputs& in) const override { return fresnel(1.0f, in); }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        if (smooth() || !(lobes & kGlossyLobe)) return 0;
        auto h = reflectionHalfVector(wo, wi);
        return h ? lobeAt(in.at).reflectionPdf(wo, *h) : 0.0f;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (wo.z <= 0 || !(lobes & this->lobes())) return std::nullopt;
        if (smooth()) return sampleMirror(wo, in);
        // GGX samples visible normals, which never face away from wo, so only the reflected
        // wi that ends up below the horizon is lost (that energy is what single scattering
        // misses); Beckmann's normals can face away, and those draws are lost too.
        Vec3 h = lobeAt(in.at).sampleHalfVector(wo, u);
        if (dot(wo, h) <= 0) return std::nullopt;
        // Weighted through eval()/pdf(); for GGX the weight reduces analytically to
        // F G2 / G1(wo) (Heitz 2018).
        return weightedSample(wo, reflect(wo, h), in, mode, lobes);
    }

private:
    bool smooth() const { return !texturedRoughness_ && lobe_.smooth(); }

    // The distribution at a hit: the constant one, or the textured roughness looked up there.
    Distribution lobeAt(const TexturePoint& at) const {
        if (!texturedRoughness_) return lobe_;
        float ax = alphaOf(roughness_.u.eval(at), roughness_.toAlpha);
        float ay = alphaOf(roughness_.v.eval(at), roughness_.toAlpha);
        return Distribution(std::max(ax, kSmoothAlpha), std::max(ay, kSmoothAlpha));
    }

    // Fresnel reflectance of a microfacet seen at cos(theta) = wo.h. Textured indices are
    // kept physical texel by texel: eta > 0 (at least kMinEta), k >= 0.
    Color fresnel(float cosTheta, const MaterialInputs& in) const {
        if (!ior_) return fresnelSchlick(in.tint, cosTheta);
        Color eta = vmax(ior_->eta.eval(in.at), Color(kMinEta)), k = vmax(ior_->k.eval(in.at), Color(0.0f));
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
    MicrofacetRoughness roughness_;
    bool texturedRoughness_;
    Distribution lobe_;  // with constant roughness
};

// The conductor with the roughness's distribution.
MaterialPtr conductorOf(ColorParam reflectance, std::optional<ComplexIorParam> ior, MicrofacetRoughness roughness) {
    if (roughness.distribution == MicrofacetDistribution::Beckmann)
        return std::make_shared<Conductor<Beckmann>>(std::move(reflectance), std::move(ior), std::move(roughness));
    return std::make_shared<Conductor<GGX>>(std::move(reflectance), std::move(ior), std::move(roughness));
}

}  // namespace

MaterialPtr makeConductor(ColorParam reflectance, float roughness) {
    return makeConductor(std::move(reflectance), MicrofacetRoughness{roughness, roughness, RoughnessToAlpha::Square});
}

MaterialPtr makeConductor(ColorParam reflectance, GgxAlpha alpha) {
    return makeConductor(std::move(reflectance), MicrofacetRoughness{alpha.x, alpha.y, RoughnessToAlpha::Identity});
}

MaterialPtr makeConductor(ColorParam reflectance, MicrofacetRoughness roughness) {
    return conductorOf(std::move(reflectance), std::nullopt, std::move(roughness));
}

MaterialPtr makeConductor(ComplexIor ior, GgxAlpha alpha) {
    return makeConductor(ComplexIorParam{ior.eta, ior.k}, MicrofacetRoughness{alpha.x, alpha.y, RoughnessToAlpha::Identity});
}

MaterialPtr makeConductor(ComplexIorParam ior, MicrofacetRoughness roughness) {
    return conductorOf(ColorParam(Color(1.0f)), std::move(ior), std::move(roughness));
}

}  // namespace photon
