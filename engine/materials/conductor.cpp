// Rough metal: GGX microfacet reflection (Walter et al. 2007) with Schlick's Fresnel
// from the tint F0; roughness 0 becomes an ideal mirror with the same Fresnel.
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"

namespace photon {
namespace {

class Conductor final : public Material {
public:
    Conductor(ColorParam reflectance, float roughness)
        : Material(std::move(reflectance)), ggx_{roughnessToAlpha(roughness)} {}

    unsigned lobes() const override { return smooth() ? kDeltaLobe : kGlossyLobe; }

    // f = F(wo.h) D G2 / (4 cos_o cos_i), Torrance-Sparrow with the height-correlated
    // Smith G2 (see microfacet.h). Zero unless wo and wi are both above the surface.
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        if (smooth() || !(lobes & kGlossyLobe)) return Color(0.0f);
        auto h = reflectionHalfVector(wo, wi);
        if (!h) return Color(0.0f);
        return fresnelSchlick(in.tint, dot(wo, *h)) * ggx_.reflectionNoFresnel(wo, wi, *h);
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs&, unsigned lobes) const override {
        if (smooth() || !(lobes & kGlossyLobe)) return 0;
        auto h = reflectionHalfVector(wo, wi);
        return h ? ggx_.reflectionPdf(wo, *h) : 0.0f;
    }

    std::optional<BSDFSample> sample(Vec3 wo, float, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (wo.z <= 0 || !(lobes & this->lobes())) return std::nullopt;
        if (smooth()) return sampleMirror(wo, in.tint);
        // Visible normals never face away from wo, so only the reflected wi that ends up
        // below the horizon is lost (that energy is what single scattering misses).
        Vec3 wi = reflect(wo, ggx_.sampleVisibleNormal(wo, u));
        // Weighted through eval()/pdf(); the weight reduces analytically to F G2 / G1(wo)
        // (Heitz 2018).
        return weightedSample(wo, wi, in, mode, lobes);
    }

private:
    bool smooth() const { return ggx_.alpha < kSmoothAlpha; }

    // The alpha -> 0 limit of the microfacet lobe: all microfacets face n, so h = n,
    // G = 1 and the reflectance is the Schlick Fresnel at the incidence angle.
    static BSDFSample sampleMirror(Vec3 wo, Color tint) {
        BSDFSample s;
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = fresnelSchlick(tint, wo.z);
        s.pdf = 1;
        s.delta = true;
        return s;
    }

    GGX ggx_;
};

}  // namespace

MaterialPtr makeConductor(ColorParam reflectance, float roughness) {
    return std::make_shared<Conductor>(std::move(reflectance), roughness);
}

}  // namespace photon
