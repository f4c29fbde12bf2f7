// Picks the light a shadow ray goes to from a surface point (render.light_sampler).
//
// "power": in proportion to each light's power wherever the point is, as photons are
// emitted (LightSampler). "spatial" (the default): infinite lights (the environment, the
// sun) keep their power's share, and among the finite ones a light is picked in proportion
// to a bound on the light it could bring to the point (LightBounds::importance): near
// lights over far ones, lights facing the point over lights facing away, lights above the
// surface over lights below it, none at all where every finite light's bound is zero. Like
// pbrt-v4's light samplers (4th ed., sec. 12.6): exhaustively up to kMaxExhaustive finite
// lights, through a tree of bounds beyond (LightTree).
//
// A pick and probability() at the same point and normal agree to the bit, so a BSDF sample
// that finds a light weighs itself against the light sample exactly (shading.h).
#pragma once
#include <cstdint>
#include <vector>
#include "lights/light_sampler.h"
#include "lights/light_tree.h"
#include <photon/render_settings.h>

namespace photon {

class DirectLightSampler {
public:
    DirectLightSampler() = default;
    DirectLightSampler(const LightSampler& byPower, LightSamplerKind kind);

    // The light for a shadow ray from p, whose light is kept only from above n (n = 0: from
    // everywhere). Index and probability as in LightSampler::Pick; no light where none can
    // reach p.
    LightSampler::Pick pick(float u, Vec3 p, Vec3 n) const;
    // The probability pick(., p, n) returns light i (an index of the power sampler) with.
    float probability(size_t i, Vec3 p, Vec3 n) const;

    // Every finite light's bound is evaluated at each shadow ray up to this many (O(n), but
    // exact per light); the tree beyond (O(log n), but its nodes' bounds are loose where a
    // point sits among their lights). Path-traced floors under grids of small lamps, equal
    // time: 144 lamps, exhaustive 0.055 relative noise against the tree's 0.20; 576 lamps,
    // the tree 0.30 against 0.88 (docs/path.md).
    static constexpr size_t kMaxExhaustive = 256;

private:
    // With one finite light there is nothing to choose: its bound could only say when it
    // cannot reach the point, which its light sample finds out as cheaply (a zero BSDF or
    // cosine, before any shadow ray).
    // Lights no sample is taken toward (an emitting medium) are left out of the choice
    // likewise, so that "power" picks them only where nothing else is asked of it.
    bool spatial() const { return kind_ == LightSamplerKind::Spatial && (finite_.size() > 1 || unsampled_); }
    // Each finite light's importance at p, into `out` (finite_.size() of them); their sum.
    float importances(Vec3 p, Vec3 n, float* out) const;
    // The probability pick returns infinite light i with.
    float infiniteProbability(size_t i) const;

    const LightSampler* byPower_ = nullptr;
    LightSamplerKind kind_ = LightSamplerKind::Power;
    LightImportances finite_;               // the finite lights' bounds, in the power sampler's order
    std::vector<uint32_t> finiteLight_;     // their indices in the power sampler
    std::vector<int32_t> finiteSlot_;       // by light: its place in finite_, or -1 if infinite
    std::vector<uint32_t> infinite_;        // the infinite lights
    std::vector<float> infiniteCdf_;        // by power among themselves
    float finiteShare_ = 0;                 // the finite lights' share of the power
    bool unsampled_ = false;                // some light is never sampled directly
    double infinitePower_ = 0;              // the infinite lights' share of all the power
    LightTree tree_;                        // over finite_, beyond kMaxExhaustive of them
};

}  // namespace photon
