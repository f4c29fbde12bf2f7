// Translucent sheet (lamp shade, curtain, paper): Lambertian reflection R / pi back to
// the side light arrives from and Lambertian transmission T / pi to the other side, both
// diffuse lobes (like pbrt-v4's DiffuseTransmissionBxDF, its "diffusetransmission"). The
// sheet has no thickness and both faces alike, so R + T <= 1 keeps it energy-conserving
// and f(wo, wi) = f(wi, wo) makes it reciprocal (either lobe depends only on whether wo
// and wi are on the same side). The reflectance is the material's tint.
#include "materials/material.h"
#include "math/sampling.h"

namespace photon {
namespace {

class DiffuseTransmission final : public Material {
public:
    DiffuseTransmission(ColorParam reflectance, ColorParam transmittance)
        : Material(std::move(reflectance)), transmittance_(std::move(transmittance)) {}

    unsigned lobes() const override { return kDiffuseLobe; }
    bool transmits() const override { return true; }
    bool textured() const override { return Material::textured() || transmittance_.textured(); }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        if (!(lobes & kDiffuseLobe) || wo.z == 0 || wi.z == 0) return Color(0.0f);
        return (sameSide(wo, wi) ? in.tint : transmittance(in)) * kInvPi;
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        if (!(lobes & kDiffuseLobe) || wo.z == 0 || wi.z == 0) return 0;
        float pReflect = reflectProbability(in);
        return (sameSide(wo, wi) ? pReflect : 1.0f - pReflect) * cosineHemispherePdf(std::abs(wi.z));
    }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode,
                                     unsigned lobes) const override {
        if (!(lobes & kDiffuseLobe) || wo.z == 0) return std::nullopt;
        Vec3 wi = sampleCosineHemisphere(u);
        if (wi.z <= 0) return std::nullopt;  // on the horizon: pdf 0
        float pReflect = reflectProbability(in);
        bool reflects = uLobe < pReflect;
        // Reflection stays on wo's side, transmission crosses to the other.
        if (reflects != (wo.z > 0)) wi.z = -wi.z;
        float pLobe = reflects ? pReflect : 1.0f - pReflect;
        // f |cos| / pdf = (colour / pi) cos / (pLobe cos / pi): the lobe's colour over its
        // choice probability, without variance from the direction.
        BSDFSample s;
        s.wi = wi;
        s.pdf = pLobe * cosineHemispherePdf(std::abs(wi.z));
        s.weight = (reflects ? in.tint : transmittance(in)) / pLobe;
        return s;
    }

private:
    static bool sameSide(Vec3 wo, Vec3 wi) { return (wo.z > 0) == (wi.z > 0); }
    Color transmittance(const MaterialInputs& in) const { return transmittance_.eval(in.at); }

    // Each lobe in proportion to its largest channel (the weights are then at most one
    // over the sum, so the photon walk's roulette sees no spikes); an all-black sheet
    // reflects, with weight zero.
    float reflectProbability(const MaterialInputs& in) const {
        float r = std::max(0.0f, maxComponent(in.tint)), t = std::max(0.0f, maxComponent(transmittance(in)));
        return r + t > 0 ? r / (r + t) : 1.0f;
    }

    ColorParam transmittance_;
};

}  // namespace

MaterialPtr makeDiffuseTransmission(ColorParam reflectance, ColorParam transmittance) {
    return std::make_shared<DiffuseTransmission>(std::move(reflectance), std::move(transmittance));
}

}  // namespace photon
