// A blend of two materials, f = (1 - t) f_a + t f_b with t a constant or a texture (moss on
// stone, worn paint), evaluated and sampled as materials/material_mixture.h says.
#include "materials/material_mixture.h"

namespace photon {
namespace {

class MixMaterial final : public Material {
public:
    // The mixture's own tint is white: each part applies its own colour, and what reads
    // "tint x a factor" (radiosity's diffuse reflectance, the denoiser's albedo) sees the
    // parts' colours through eval alone.
    MixMaterial(MaterialPtr a, MaterialPtr b, FloatParam amount)
        : Material(Color(1.0f)), a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)) {}

    unsigned lobes() const override { return a_->lobes() | b_->lobes(); }
    bool twoSided() const override { return a_->twoSided(); }  // both agree (makeMix checks)
    bool textured() const override { return amount_.textured() || a_->textured() || b_->textured(); }
    bool transmits() const override { return a_->transmits() || b_->transmits(); }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        return mixtureAt(in.at).eval(wo, wi, mode, lobes);
    }
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        return mixtureAt(in.at).pdf(wo, wi, lobes);
    }
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        return mixtureAt(in.at).sample(wo, uLobe, u, mode, lobes);
    }
    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override { return mixtureAt(in.at).diffuseShare(wo); }

private:
    MaterialMixture mixtureAt(const TexturePoint& at) const {
        return {*a_, a_->inputsAt(at), *b_, b_->inputsAt(at), amount_.eval(at)};
    }

    MaterialPtr a_, b_;
    FloatParam amount_;
};

}  // namespace

MaterialPtr makeMix(MaterialPtr a, MaterialPtr b, FloatParam amount) {
    if (a->twoSided() != b->twoSided())
        throw std::invalid_argument("a mix cannot join a one-sided material (a dielectric) with a two-sided one");
    // A hair fibre's frame runs along the fibre; the other part's would not.
    if (a->alignsToTangent() || b->alignsToTangent()) throw std::invalid_argument("a mix cannot include a hair material");
    return std::make_shared<MixMaterial>(std::move(a), std::move(b), std::move(amount));
}

}  // namespace photon
