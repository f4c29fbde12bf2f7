// Rough dielectric boundary (frosted glass, etched ice): GGX microfacets that each reflect
// and refract like the smooth boundary (Walter, Marschner, Li, Torrance 2007, "Microfacet
// Models for Refraction through Rough Surfaces", EGSR). Both lobes are glossy. A nearly
// smooth or index-matched boundary is the smooth dielectric (dielectric.cpp) instead.
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet_refraction.h"

namespace photon {
namespace {

class RoughDielectric final : public Material {
public:
    RoughDielectric(float ior, float alpha) : Material(Color(1.0f)), eta_(ior), ggx_{alpha} {}

    unsigned lobes() const override { return kGlossyLobe; }
    bool twoSided() const override { return false; }  // inside and outside differ
    std::optional<float> refractiveIndex() const override { return eta_; }

    // Reflection: F D G / (4 |cos_o cos_i|) (Walter eq. 20). Transmission (Walter eq. 21,
    // divided through by n_o^2):
    //   f = (1 - F) D G |wi.h| |wo.h| / (|cos_i cos_o| |wo + etap wi|^2),
    // the radiance form, which carries the (n_o / n_i)^2 compression of radiance across the
    // boundary (Veach 1997, sec. 5.2). Importance is its adjoint f*(wo, wi) = f(wi, wo),
    // which is etap^2 times as large. F is the microfacet's reflectance (microfacetFresnel);
    // G is the height-correlated Smith G2 of microfacet.h, symmetric in wo and wi (for
    // transmission the exact height-correlated form differs, Heitz 2014 sec. 6; pbrt-v4
    // uses this one too).
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        if (!(lobes & kGlossyLobe)) return Color(0.0f);
        auto p = microfacetPair(wo, wi, eta_);
        if (!p) return Color(0.0f);
        float F = microfacetFresnel(*p, wo, wi, eta_);
        float DG = ggx_.D(p->h) * ggx_.G2(wo, wi);
        float cosines = std::abs(wo.z * wi.z);
        if (p->reflection) return in.tint * (F * DG / (4.0f * cosines));
        float f = (1.0f - F) * DG * std::abs(dot(wi, p->h) * dot(wo, p->h)) / (cosines * p->length2);
        if (mode == TransportMode::Importance) f *= p->etap * p->etap;
        return in.tint * f;
    }

    // Visible normals, then reflection with probability F and refraction otherwise:
    // the density of wi is D_wo(h) times F or 1 - F times d(omega_h)/d(omega_i).
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs&, unsigned lobes) const override {
        if (!(lobes & kGlossyLobe)) return 0;
        auto p = microfacetPair(wo, wi, eta_);
        if (!p) return 0;
        float F = microfacetFresnel(*p, wo, wi, eta_);
        float choice = p->reflection ? F : 1.0f - F;
        return visibleNormalDensity(ggx_, wo, p->h) * choice * halfVectorJacobian(*p, wo, wi);
    }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (!(lobes & kGlossyLobe) || wo.z == 0) return std::nullopt;
        Vec3 h = sampleVisibleNormalEitherSide(ggx_, wo, u);
        // fresnelDielectric reads which side wo is on from the sign of wo.h, and returns 1
        // under total internal reflection, so refraction is then never chosen. Choosing
        // by F cancels F out of the weight, as for the smooth boundary.
        float F = fresnelDielectric(dot(wo, h), eta_);
        Vec3 wi;
        if (uLobe < F) {
            wi = reflect(wo, h);
        } else {
            auto r = refract(wo, h, eta_);
            if (!r) return std::nullopt;  // only reachable through float round-off
            wi = r->wt;
        }
        // A direction that leaves on the wrong side of the macro surface is lost: that is
        // the energy single scattering misses. The rest is weighted through eval() and
        // pdf(), so weight == eval |cos| / pdf holds exactly; it reduces to G2 / G1(wo)
        // (times 1 / etap^2 for refracted radiance).
        auto p = microfacetPair(wo, wi, eta_);
        if (!p || p->reflection != (uLobe < F)) return std::nullopt;
        float density = pdf(wo, wi, in, lobes);
        if (!(density > 0)) return std::nullopt;
        BSDFSample s;
        s.wi = wi;
        s.pdf = density;
        s.weight = eval(wo, wi, in, mode, lobes) * (std::abs(wi.z) / density);
        return s;
    }

private:
    float eta_;
    GGX ggx_;
};

}  // namespace

MaterialPtr makeRoughDielectric(float ior, float roughness) {
    float alpha = roughnessToAlpha(roughness);
    // Below kSmoothAlpha the lobes are narrower than floats resolve: the alpha -> 0 limit
    // (all microfacets face z, G = 1) is the smooth boundary. With equal indices nothing
    // refracts and the generalised half vector of the straight-through pair is undefined:
    // light passes unchanged, as through the smooth boundary of index 1.
    if (alpha < kSmoothAlpha || ior == 1.0f) return makeDielectric(ior);
    return std::make_shared<RoughDielectric>(ior, alpha);
}

}  // namespace photon
