// A material whose roughness varies over the surface (a roughness map): the material made
// at a ladder of roughnesses (RoughnessLevels), and at a point of roughness r the blend of
// the two levels either side, f = (1 - t) f_k + t f_(k+1) (a mixture, so reciprocal,
// energy-conserving and sampled as one: materials/material_mixture.h). Every level keeps
// its own precomputed tables (a coat's albedo), which a roughness that changes from texel
// to texel could not have.
//
// The levels: 0 (smooth), then 24 from 0.01 to 1 spaced evenly in log r (each 1.22 times
// the last, its GGX alpha 1.49 times), t linear in log r between them (in r below 0.01,
// where the lobe is a mirror's to within a degree). Between levels the lobe is a blend of
// two lobes rather than one between them: against the material made at r, the lobe's
// shape differs by an L1 of ~0.02 of its albedo (tests/test_textured_roughness.cpp); evenly
// spaced levels 1/16 apart measured 0.08 at r = 0.1, where neighbouring alphas differ 4x.
#include <algorithm>
#include <cmath>
#include <vector>
#include "materials/material_mixture.h"

namespace photon {
namespace {

constexpr int kRoughLevels = 24;
constexpr float kFirstRough = 0.01f;

float levelRoughness(int k) {
    return k == 0 ? 0.0f : kFirstRough * std::pow(1.0f / kFirstRough, float(k - 1) / float(kRoughLevels - 1));
}

class TexturedRoughness final : public Material {
public:
    TexturedRoughness(ColorParam tint, FloatParam roughness, float exponent, std::shared_ptr<const RoughnessLevels> levels)
        : Material(std::move(tint)), roughness_(std::move(roughness)), exponent_(exponent), levels_(std::move(levels)) {
        for (const MaterialPtr& m : *levels_) lobes_ |= m->lobes();
    }

    unsigned lobes() const override { return lobes_; }
    bool twoSided() const override { return (*levels_)[0]->twoSided(); }
    bool textured() const override { return true; }
    bool transmits() const override { return (*levels_)[0]->transmits(); }
    std::optional<float> refractiveIndex() const override { return (*levels_)[0]->refractiveIndex(); }

    Color eval(Vec3 wo, Vec3 wi, const MaterialInputs& in, TransportMode mode, unsigned lobes) const override {
        return at(in).eval(wo, wi, mode, lobes);
    }
    float pdf(Vec3 wo, Vec3 wi, const MaterialInputs& in, unsigned lobes) const override {
        return at(in).pdf(wo, wi, lobes);
    }
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, const MaterialInputs& in, TransportMode mode,
                                     unsigned lobes) const override {
        return at(in).sample(wo, uLobe, u, mode, lobes);
    }
    float diffuseShare(Vec3 wo, const MaterialInputs& in) const override { return at(in).diffuseShare(wo); }

private:
    // The levels are made with any colour: this material's, read at the point (in), is what
    // each of them is given.
    MaterialMixture at(const MaterialInputs& in) const {
        float r = std::clamp(roughness_.eval(in.at), 0.0f, 1.0f);
        if (exponent_ != 1) r = std::pow(r, exponent_);
        int k = 0;
        float t = r / kFirstRough;
        if (r >= kFirstRough) {
            const float x = 1.0f + float(kRoughLevels - 1) * std::log(r / kFirstRough) / std::log(1.0f / kFirstRough);
            k = std::min(int(x), kRoughLevels - 1);
            t = x - float(k);
        }
        const RoughnessLevels& l = *levels_;
        return {*l[size_t(k)], in, *l[size_t(k) + 1], in, std::clamp(t, 0.0f, 1.0f)};
    }

    FloatParam roughness_;
    float exponent_;
    std::shared_ptr<const RoughnessLevels> levels_;
    unsigned lobes_ = 0;
};

}  // namespace

std::shared_ptr<const RoughnessLevels> makeRoughnessLevels(const std::function<MaterialPtr(float)>& make) {
    auto levels = std::make_shared<RoughnessLevels>();
    for (int k = 0; k <= kRoughLevels; ++k) levels->push_back(make(levelRoughness(k)));
    return levels;
}

MaterialPtr makeTexturedRoughness(ColorParam tint, FloatParam roughness, float exponent,
                                  std::shared_ptr<const RoughnessLevels> levels) {
    return std::make_shared<TexturedRoughness>(std::move(tint), std::move(roughness), exponent, std::move(levels));
}

}  // namespace photon
