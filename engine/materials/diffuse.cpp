// Lambertian reflector: f = albedo / pi, the ideal matte surface (Lambert 1760).
#include "materials/material.h"
#include "math/sampling.h"

namespace photon {
namespace {

class Diffuse final : public Material {
public:
    explicit Diffuse(ColorParam albedo) : Material(std::move(albedo)) {}

    unsigned lobes() const override { return kDiffuseLobe; }
    bool lambertian() const override { return true; }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode, unsigned lobes) const override {
        // Reflection only, front side only: light from below the surface never reaches wo.
        if (!(lobes & kDiffuseLobe) || wo.z <= 0 || wi.z <= 0) return Color(0.0f);
        return in.tint * kInvPi;
    }

    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs&, unsigned lobes) const override {
        if (!(lobes & kDiffuseLobe) || wo.z <= 0 || wi.z <= 0) return 0;
        return cosineHemispherePdf(wi.z);
    }

    std::optional<BSDFSample> sample(Vec3 wo, float, Vec2 u, const MaterialInputs& in, TransportMode,
                                     unsigned lobes) const override {
        if (!(lobes & kDiffuseLobe) || wo.z <= 0) return std::nullopt;
        // Cosine-weighted sampling matches f |cos| exactly, so the weight is the albedo:
        // (albedo / pi) cos / (cos / pi).
        Vec3 wi = sampleCosineHemisphere(u);
        if (wi.z <= 0) return std::nullopt;  // on the horizon: pdf 0
        BSDFSample s;
        s.wi = wi;
        s.weight = in.tint;
        s.pdf = cosineHemispherePdf(wi.z);
        return s;
    }
};

}  // namespace

MaterialPtr makeDiffuse(ColorParam albedo) { return std::make_shared<Diffuse>(std::move(albedo)); }

}  // namespace photon
