// A Lambertian base under a dielectric coat of index `ior`, GGX-rough or smooth: what
// plastic and coated_diffuse share. The coat's specular reflection, the sampling and the
// lobe choice live here; each model says how much of the base shows through the coat
// (its diffuse term) and how bright the coat looks from a direction (for the lobe choice).
#pragma once
#include "materials/fresnel.h"
#include "materials/material.h"
#include "materials/microfacet.h"

namespace photon {

class CoatOverDiffuse : public Material {
public:
    CoatOverDiffuse(ColorParam albedo, float ior, float roughness)
        : Material(std::move(albedo)), ior_(ior), ggx_{roughnessToAlpha(roughness)} {}

    unsigned lobes() const override { return kDiffuseLobe | (smooth() ? kDeltaLobe : kGlossyLobe); }
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override;
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override;
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override;
    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override {
        return 1.0f - specularProbability(wo, in.tint, kAllLobes);
    }

protected:
    bool smooth() const { return ggx_.smooth(); }
    float fresnel(float cosTheta) const { return fresnelDielectric(cosTheta, ior_); }
    // The coat's specular reflection F(wo.h) D G2 / (4 cos_o cos_i) (Walter et al. 2007,
    // eq. 20); zero when smooth (its mirror is a delta lobe).
    float specular(Vec3 wo, Vec3 wi) const;
    // The base seen through the coat, both directions above the surface.
    virtual Color diffuse(Vec3 wo, Vec3 wi, Color albedo) const = 0;
    // The coat's directional albedo at cos(theta_o), for choosing between the lobes.
    virtual float coatAlbedo(float cosThetaO) const = 0;

    float ior_;
    GGX ggx_;

private:
    float specularProbability(Vec3 wo, Color albedo, unsigned lobes) const;
    BSDFSample sampleCoatMirror(Vec3 wo, float pSpec) const;
    static constexpr float kMinLobeProbability = 0.05f;
};

}  // namespace photon
