// Coated diffuse: a Lambertian base (albedo rho, the tint) under a clear dielectric coat
// of index eta, smooth or GGX-rough, with nothing between them (no absorbing or scattering
// medium layer, no thickness). The coat reflects specularly; light it transmits reaches
// the base, is scattered there, and bounces between base and coat until it leaves.
//
//   f = F(wo.h) D G2 / (4 cos_o cos_i)                                        (coat)
//     + rho (1 - E(cos_o)) (1 - E(cos_i)) / (pi eta^2 (1 - rho Fint))         (base)
//
// E(cos) is the coat's directional albedo: Fresnel F(cos) when smooth, the GGX + Fresnel
// lobe's albedo when rough (tabulated below). 1 - E is the share the coat lets through,
// in or out; 1/eta^2 the radiance compression of refraction; 1 / (1 - rho Fint) sums the
// internal reflections, Fint being the share of the base's (diffuse) light the coat sends
// back down. This is the coupled model of Kelemen & Szirmay-Kalos 2001 ("A Microfacet
// Based Coupled Specular-Matte BRDF Model with Importance Sampling", EG short papers) and
// Weidlich & Wilkie 2007 ("Arbitrarily Layered Micro-Facet Surfaces", sec. 4), the family
// Tungsten's rough_plastic belongs to. Fint comes from the reciprocity of the boundary, which
// gives eta^2 (1 - Fint) = 1 - Ebar, Ebar = 2 int E(mu) mu dmu the coat's cosine-weighted
// albedo from outside (exact for a smooth coat: Veach 1997 sec. 5.2 integrated over both
// hemispheres). With that choice a white base gives albedo E(cos_i) + (1 - E(cos_i)) = 1
// at every angle: nothing is lost, and any rho < 1 keeps less.
//
// Measured against a random walk between coat and base (tests/test_coated_diffuse.cpp;
// a rough coat walked on its microsurface, Heitz et al. 2016, which loses no light):
// exact for a smooth coat, and for a white base under any coat (albedo 1 both). Under a
// rough coat the specular lobe here is single-scattering GGX: what the coat's facets
// reflect into one another, which a real coat sends back up, this model passes to the
// base instead. Over a dark base that makes it darker than the walk: at most 0.009 in
// albedo over the cases tested (roughness up to 0.8, worst at grazing light). The Lambertian base forgets where light
// came from, so how much the coat lets through is all that matters of its transmission.
// Not modelled: anisotropic roughness, and a medium between coat and base (pbrt-v4's
// thickness, albedo and g).
#include <algorithm>
#include "materials/coat_albedo.h"
#include "materials/coat_over_diffuse.h"

namespace photon {
namespace {

class CoatedDiffuse final : public CoatOverDiffuse {
public:
    CoatedDiffuse(ColorParam albedo, float ior, float roughness)
        : CoatOverDiffuse(std::move(albedo), ior, roughness), coat_(ior_, ggx_) {
        internalReflectance_ = std::clamp(1.0f - (1.0f - coat_.cosineWeighted()) / (ior_ * ior_), 0.0f, 1.0f);
    }

private:
    Color diffuse(Vec3 wo, Vec3 wi, Color albedo) const override {
        float through = (1.0f - coatAlbedo(wo.z)) * (1.0f - coatAlbedo(wi.z)) * kInvPi / (ior_ * ior_);
        Color internal = Color(1.0f) - albedo * internalReflectance_;
        return albedo * through / internal;
    }

    float coatAlbedo(float cosThetaO) const override { return coat_(cosThetaO); }

    CoatAlbedo coat_;
    float internalReflectance_ = 0;  // Fint
};

}  // namespace

MaterialPtr makeCoatedDiffuse(ColorParam albedo, float ior, float roughness) {
    return std::make_shared<CoatedDiffuse>(std::move(albedo), ior, roughness);
}

}  // namespace photon
