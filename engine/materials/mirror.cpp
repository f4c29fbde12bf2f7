// Perfect specular reflector tinted by `reflectance`: a single Dirac lobe.
#include "materials/material.h"

namespace photon {
namespace {

class Mirror final : public Material {
public:
    explicit Mirror(ColorParam reflectance) : Material(std::move(reflectance)) {}

    unsigned lobes() const override { return kDeltaLobe; }
    std::optional<SmoothSpecular> smoothSpecular() const override { return SmoothSpecular{0.0f}; }

    // A Dirac lobe has no finite value or density for any given wi.
    Color eval(Vec3, Vec3, const MaterialInputs&, TransportMode, unsigned) const override { return Color(0.0f); }
    float pdf(Vec3, Vec3, const MaterialInputs&, unsigned) const override { return 0; }

    std::optional<BSDFSample> sample(Vec3 wo, float, Vec2, const MaterialInputs& in, TransportMode,
                                     unsigned lobes) const override {
        if (!(lobes & kDeltaLobe)) return std::nullopt;
        if (wo.z <= 0) return std::nullopt;
        // f = R delta(wi - mirror(wo)) / |cos| (pbrt-v4 sec. 9.3), so f |cos| / pdf = R.
        BSDFSample s;
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = in.tint;
        s.pdf = 1;
        s.delta = true;
        return s;
    }
};

}  // namespace

MaterialPtr makeMirror(ColorParam reflectance) { return std::make_shared<Mirror>(std::move(reflectance)); }

}  // namespace photon
