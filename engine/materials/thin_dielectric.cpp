// Thin dielectric slab (window glass, a soap film) as one surface: light entering it
// bounces between its two parallel faces, and every bounce either leaves through the
// front (adding to the reflection) or through the back (adding to the transmission).
// Whatever leaves through the back is refracted twice, in and out again, so it keeps
// wo's direction: transmission goes straight through, -wo, and the medium on both sides is
// the same, so radiance is not scaled. Both lobes are Dirac deltas; the slab has no inside
// and outside, so it is two-sided (pbrt-v4 sec. 9.5.2, ThinDielectricBxDF).
#include "materials/fresnel.h"
#include "materials/material.h"

namespace photon {
namespace {

class ThinDielectric final : public Material {
public:
    explicit ThinDielectric(float ior) : Material(Color(1.0f)), ior_(ior) {}

    unsigned lobes() const override { return kDeltaLobe; }

    Color eval(Vec3, Vec3, const MaterialInputs&, TransportMode, unsigned) const override { return Color(0.0f); }
    float pdf(Vec3, Vec3, const MaterialInputs&, unsigned) const override { return 0; }

    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2, const MaterialInputs& in, TransportMode,
                                     unsigned lobes) const override {
        if (!(lobes & kDeltaLobe) || wo.z == 0) return std::nullopt;
        float R = slabReflectance(std::abs(wo.z));
        // Choosing by R makes each weight R/R or (1-R)/(1-R), as for the smooth boundary.
        BSDFSample s;
        s.wi = uLobe < R ? Vec3(-wo.x, -wo.y, wo.z) : -wo;
        s.pdf = uLobe < R ? R : 1.0f - R;
        s.weight = in.tint;
        s.delta = true;
        return s;
    }

private:
    // One face reflects R = F(cos_o) and transmits T = 1 - R; the inner face sees the same
    // angle (Snell twice), so the same R. Summing the paths that bounce 2k times inside,
    // R' = R + T^2 R (1 + R^2 + R^4 + ...) = R + T^2 R / (1 - R^2), and T' = 1 - R'
    // (pbrt-v4 sec. 9.5.2). At normal incidence this is 2R / (1 + R).
    float slabReflectance(float cosTheta) const {
        float R = fresnelDielectric(cosTheta, ior_);
        if (R >= 1.0f) return 1.0f;  // only reachable for ior < 1 beyond the critical angle
        float T = 1.0f - R;
        return R + T * T * R / (1.0f - R * R);
    }

    float ior_;
};

}  // namespace

MaterialPtr makeThinDielectric(float ior) { return std::make_shared<ThinDielectric>(ior); }

}  // namespace photon
