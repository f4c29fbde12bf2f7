// Smooth dielectric boundary (glass, water): exact Fresnel reflection plus Snell
// refraction, both Dirac lobes. The outside medium has index 1.
#include "materials/fresnel.h"
#include "materials/material.h"

namespace photon {
namespace {

class Dielectric final : public Material {
public:
    explicit Dielectric(float ior) : Material(Color(1.0f)), ior_(ior) {}

    unsigned lobes() const override { return kDeltaLobe; }
    bool twoSided() const override { return false; }  // inside and outside differ
    std::optional<SmoothSpecular> smoothSpecular() const override { return SmoothSpecular{ior_}; }

    Color eval(Vec3, Vec3, const MaterialInputs&, TransportMode, unsigned) const override { return Color(0.0f); }
    float pdf(Vec3, Vec3, const MaterialInputs&, unsigned) const override { return 0; }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (!(lobes & kDeltaLobe) || wo.z == 0) return std::nullopt;
        // wo.z < 0 means wo is inside; fresnelDielectric inverts the ratio for us, and
        // returns 1 under total internal reflection, so refraction is never chosen then.
        float F = fresnelDielectric(wo.z, ior_);
        // Choosing reflection with probability F makes each weight F/F or (1-F)/(1-F):
        // no variance from the Fresnel split (pbrt-v4 sec. 9.5).
        if (uLobe < F) return reflection(wo, F, in.tint);
        return transmission(wo, 1.0f - F, in.tint, mode);
    }

private:
    static BSDFSample reflection(Vec3 wo, float F, Color tint) {
        BSDFSample s;
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = tint;
        s.pdf = F;
        s.delta = true;
        return s;
    }

    std::optional<BSDFSample> transmission(Vec3 wo, float T, Color tint, TransportMode mode) const {
        auto r = refract(wo, Vec3(0, 0, 1), ior_);
        if (!r || T <= 0) return std::nullopt;  // only reachable through float round-off
        BSDFSample s;
        s.wi = r->wt;
        // Radiance is compressed by the solid-angle change across the boundary: L / n^2
        // is invariant, so radiance arriving along wi (index n_i) leaves along wo
        // (index n_o) scaled by (n_o / n_i)^2 = 1 / etap^2, etap = n_i / n_o being the
        // index of the side wi lies in relative to wo's. Importance (adjoint transport)
        // is not scaled (Veach 1997, sec. 5.2; pbrt-v4 sec. 9.5).
        float scale = mode == TransportMode::Radiance ? 1.0f / (r->etap * r->etap) : 1.0f;
        s.weight = tint * scale;
        s.pdf = T;
        s.delta = true;
        return s;
    }

    float ior_;
};

}  // namespace

MaterialPtr makeDielectric(float ior) { return std::make_shared<Dielectric>(ior); }

}  // namespace photon
