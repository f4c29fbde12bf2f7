// An opaque material seen from one side only (a material's "two_sided": false, as
// Mitsuba's BSDFs are unless wrapped in its "twosided"): the side its surface's normal faces
// scatters as the base does, the other is black. Integrators keep such a surface's normal
// as the mesh gives it (Material::twoSided), so light arriving at the back finds wo.z < 0
// here: it is absorbed, and a camera path that sees the back ends there. Like the normal
// map's wrapper it reports no Lambertian or smooth-specular shortcut, so photons meet it one
// by one rather than in the photon walk's lanes, which shade both sides.
#include "materials/material.h"

namespace photon {
namespace {

class OneSided final : public Material {
public:
    explicit OneSided(MaterialPtr base) : Material(base->tint()), base_(std::move(base)) {}

    unsigned lobes() const override { return base_->lobes(); }
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        return wo.z > 0 ? base_->eval(wo, wi, in, mode, lobes) : Color(0.0f);
    }
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        return wo.z > 0 ? base_->pdf(wo, wi, in, lobes) : 0.0f;
    }
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        if (!(wo.z > 0)) return std::nullopt;
        return base_->sample(wo, uLobe, u, in, mode, lobes);
    }
    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override { return base_->diffuseShare(wo, in); }
    bool textured() const override { return base_->textured(); }
    bool twoSided() const override { return false; }
    bool bendsNormal() const override { return base_->bendsNormal(); }
    Vec3 bentNormal(const TexturePoint& at, Vec3 n, Vec3 ng, const SurfaceTangents& t) const override {
        return base_->bentNormal(at, n, ng, t);
    }

private:
    MaterialPtr base_;
};

}  // namespace

MaterialPtr makeOneSided(MaterialPtr base) { return std::make_shared<OneSided>(std::move(base)); }

}  // namespace photon
