// Photons sent where the camera sees them: a learned distribution over where photons leave
// the lights, after Hachisuka & Jensen 2011 ("Robust adaptive photon tracing using photon
// path visibility"), whose measure of a photon's use is whether its path reaches a visible
// point. Here the light and the four numbers that place and aim a photon (PhotonEmitter's
// uPos, uDir) are cut into cells, B per number; each cell learns what a photon leaving it
// is worth on average (the visible points it reaches, each weighted by how much its pixel
// still needs photons: the integrator's choice), and cells are picked in proportion to that
// times their share under the plain emission, mixed with the plain emission itself. Within a
// cell the numbers stay uniform, so a photon's flux times prior / probability of its cell
// keeps every estimate unbiased, and the mixture bounds that factor by 1 / kDefensive.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace photon {

class LightSampler;

class EmissionGuide {
public:
    // For a sampler with at least one light.
    explicit EmissionGuide(const LightSampler& lights);

    // Share of photons emitted as without the guide, whatever it has learned: it keeps
    // every place that reaches the image in reach, and flux factors at most 1 / 0.2.
    static constexpr double kDefensive = 0.2;

    size_t cellCount() const { return prior_.size(); }
    int binsPerNumber() const { return bins_; }
    bool trained() const { return trained_; }

    struct Choice {
        uint32_t light;  // the light sampler's index
        uint32_t cell;   // among cellCount(), the light's cells together
        float weight;    // the photon's flux factor: prior / probability of the cell
    };
    // u is an Rng::uniform() number: a multiple of 2^-24, which the cells' integer
    // thresholds split exactly, so `weight` is the inverse of the true probability.
    Choice pick(float u) const;
    // Cell c's probability (a multiple of 2^-24) and its weight, as pick() gives them.
    double probability(uint32_t cell) const;
    float weight(uint32_t cell) const { return weight_[cell]; }
    // The cell's part of [0,1)^4 for the emitter's four numbers: u[d] becomes
    // min(offset[d] + u[d] * scale, limit[d]), limit[d] the last float inside the cell
    // (rounding would otherwise carry a number just below the cell's top into the next).
    void cellBounds(uint32_t cell, float offset[4], float limit[4]) const;
    float scale() const { return 1.0f / static_cast<float>(bins_); }
    // Numbers u in [0,1)^4 moved into the cell.
    void remap(uint32_t cell, float u[4]) const;

    // What one pass of `photons` photons found: worth[c], what photons of cell c were worth
    // together, as integers summed in any order, so that the guide, and every pass after
    // it, are the same for any number of threads. Each pass counts alike: its worth is
    // scaled to sum to 1 per photon before it is added.
    void learn(std::span<const uint64_t> worth, int64_t photons);

private:
    void rebuild();
    // prior_c u_c: what cell c's photons are worth, per photon of the plain emission.
    double usefulness(size_t cell) const;
    static std::vector<uint32_t> toUnits(const std::vector<double>& probabilities);

    int bins_;                     // B: cells per number
    uint32_t perLight_;            // B^4
    std::vector<double> prior_;    // each cell's probability under plain emission
    std::vector<double> emitted_;  // photons expected from each cell so far (sum of N p_c)
    std::vector<double> worth_;    // what each cell's photons were worth so far
    // The current distribution: cell c holds the numbers k / 2^24 with
    // upper_[c - 1] <= k < upper_[c], so its probability is an exact multiple of 2^-24.
    std::vector<uint32_t> upper_;
    std::vector<float> weight_;    // prior / probability, by cell
    bool trained_ = false;
};

}  // namespace photon
