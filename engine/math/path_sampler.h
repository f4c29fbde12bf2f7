// The random numbers of one camera path, drawn one 1D or 2D draw at a time (the pixel's
// film position, the lens, a light pick, a light point, a lobe, a direction...).
//
// Independent (render.sampler = "independent"): every number from the pixel's Rng, in the
// order the calls ask for them.
//
// Stratified over passes (render.sampler = "sobol"): the path's k-th draw in pass p is
// sample p / 2 of its own Owen-scrambled Sobol draw (sobol.h), keyed by (seed, pixel, path,
// p mod 2, k), so that a pixel's passes spread each draw evenly over its domain instead of
// at random: the film positions of a pixel's first 2^m even passes fall one in each of 2^m
// strata, and so do their light points and lobe choices. Each pass's path is still a
// uniform random point, so every estimate keeps its expectation. Odd and even passes are
// two independent sequences: the error estimate compares those halves and needs them
// independent (docs/error-estimate.md). Draws past the first kStratifiedDraws come from
// the Rng: deep bounces gain little from stratification.
#pragma once
#include <cstdint>
#include "math/rng.h"
#include "math/sobol.h"

namespace photon {

class PathSampler {
public:
    static constexpr int kStratifiedDraws = 24;

    // Stratified (render.sampler "sobol") or every draw from `rng` ("independent").
    static PathSampler of(bool stratified, Rng& rng, uint64_t seed, int64_t pass, uint64_t pixel, uint64_t path) {
        return stratified ? PathSampler(rng, seed, pass, pixel, path) : PathSampler(rng);
    }
    // Every draw from `rng`.
    explicit PathSampler(Rng& rng) : rng_(rng) {}
    // Draws stratified over the passes of path `path` of pixel `pixel`.
    PathSampler(Rng& rng, uint64_t seed, int64_t pass, uint64_t pixel, uint64_t path)
        : rng_(rng),
          key_(mix64<uint64_t>(seed ^ mix64<uint64_t>((pixel << 8 | path << 1 | (static_cast<uint64_t>(pass) & 1u)) +
                                                      0x5851f42d4c957f2dull))),
          index_(static_cast<uint32_t>(pass >> 1)),
          stratified_(true) {}

    float get1D() {
        if (!stratifies()) return rng_.uniform();
        return sobol::sample1D(index_, drawKey(draw_++));
    }
    Vec2 get2D() {
        if (!stratifies()) return {rng_.uniform(), rng_.uniform()};
        const uint64_t key = drawKey(draw_++);
        // The third seed from the key by one multiply-xorshift round: seeds need only differ.
        return sobol::sample2D(index_, key, static_cast<uint32_t>(((key ^ (key >> 29)) * 0xbf58476d1ce4e5b9ull) >> 32));
    }
    // The pixel's own stream, for numbers that are not part of the path's integrand (a
    // colour's rounding dither, the count of extra paths).
    Rng& rng() { return rng_; }

private:
    bool stratifies() const { return stratified_ && draw_ < kStratifiedDraws; }
    uint64_t drawKey(int draw) const {
        return mix64<uint64_t>(key_ + 0x9e3779b97f4a7c15ull * static_cast<uint64_t>(draw + 1));
    }

    Rng& rng_;
    uint64_t key_ = 0;
    uint32_t index_ = 0;
    int draw_ = 0;
    bool stratified_ = false;
};

}  // namespace photon
