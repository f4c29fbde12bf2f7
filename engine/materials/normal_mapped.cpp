// A material seen through a normal or bump map: its BSDF unchanged, evaluated in the frame
// of the bent shading normal (integrators/common/shading.h asks for it). It reports no
// Lambertian or smooth-specular shortcut, so that photons, too, meet it one by one through
// the bent frame rather than in the photon walk's lanes, which use the unbent normal.
#include "materials/material.h"

namespace photon {
namespace {

class NormalMapped final : public Material {
public:
    // One of the two: a tangent-space normal map, or a height field.
    NormalMapped(MaterialPtr base, std::shared_ptr<const Texture> map, FloatParam height)
        : Material(base->tint()), base_(std::move(base)), map_(std::move(map)), height_(std::move(height)) {}

    unsigned lobes() const override { return base_->lobes(); }
    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        return base_->eval(wo, wi, in, mode, lobes);
    }
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        return base_->pdf(wo, wi, in, lobes);
    }
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        return base_->sample(wo, uLobe, u, in, mode, lobes);
    }
    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override { return base_->diffuseShare(wo, in); }
    bool textured() const override { return true; }
    bool twoSided() const override { return base_->twoSided(); }
    bool transmits() const override { return base_->transmits(); }
    std::optional<float> refractiveIndex() const override { return base_->refractiveIndex(); }
    bool bendsNormal() const override { return true; }
    Vec3 bentNormal(const TexturePoint& at, Vec3 n, Vec3 ng, const SurfaceTangents& t) const override {
        return map_ ? mappedNormal(*map_, at, n, ng, t.dpdu) : bumpedNormal(height_, at, n, ng, t);
    }

private:
    MaterialPtr base_;
    std::shared_ptr<const Texture> map_;
    FloatParam height_;
};

}  // namespace

MaterialPtr makeNormalMapped(MaterialPtr base, std::shared_ptr<const Texture> normalMap) {
    return std::make_shared<NormalMapped>(std::move(base), std::move(normalMap), FloatParam());
}

MaterialPtr makeBumpMapped(MaterialPtr base, FloatParam height) {
    return std::make_shared<NormalMapped>(std::move(base), nullptr, std::move(height));
}

}  // namespace photon
