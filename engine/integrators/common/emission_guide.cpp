#include "integrators/common/emission_guide.h"
#include <algorithm>
#include <cmath>
#include <numeric>
#include "lights/light_sampler.h"

namespace photon {

namespace {
constexpr uint32_t kUnits = 1u << 24;  // Rng::uniform()'s resolution

// Cells per number: 8 (4,096 cells a light) for a few lights, fewer for many, so that the
// table stays near 65k cells and each cell still sees photons in every pass of 200k.
int binsFor(size_t lights) {
    if (lights <= 16) return 8;
    if (lights <= 256) return 4;
    if (lights <= 4096) return 2;
    return 1;
}
}  // namespace

EmissionGuide::EmissionGuide(const LightSampler& lights)
    : bins_(binsFor(lights.size())), perLight_(static_cast<uint32_t>(bins_ * bins_ * bins_ * bins_)) {
    const size_t perLight = perLight_;
    prior_.resize(lights.size() * perLight);
    for (size_t i = 0; i < lights.size(); ++i)
        std::fill_n(prior_.begin() + static_cast<std::ptrdiff_t>(i * perLight), perLight,
                    static_cast<double>(lights.probability(i)) / static_cast<double>(perLight));
    emitted_.assign(prior_.size(), 0.0);
    worth_.assign(prior_.size(), 0.0);
    rebuild();
}

EmissionGuide::Choice EmissionGuide::pick(float u) const {
    const auto k = static_cast<uint32_t>(u * static_cast<float>(kUnits));
    auto cell = static_cast<uint32_t>(std::upper_bound(upper_.begin(), upper_.end(), k) - upper_.begin());
    cell = std::min<uint32_t>(cell, static_cast<uint32_t>(upper_.size() - 1));
    return {cell / perLight_, cell, weight_[cell]};
}

double EmissionGuide::probability(uint32_t cell) const {
    return static_cast<double>(upper_[cell] - (cell ? upper_[cell - 1] : 0)) / kUnits;
}

void EmissionGuide::cellBounds(uint32_t cell, float offset[4], float limit[4]) const {
    cell %= perLight_;
    const float s = scale();
    for (int d = 0; d < 4; ++d) {
        offset[d] = static_cast<float>(cell % static_cast<uint32_t>(bins_)) * s;
        limit[d] = std::nextafter(offset[d] + s, 0.0f);
        cell /= static_cast<uint32_t>(bins_);
    }
}

void EmissionGuide::remap(uint32_t cell, float u[4]) const {
    float offset[4], limit[4];
    cellBounds(cell, offset, limit);
    const float s = scale();
    for (int d = 0; d < 4; ++d) u[d] = std::min(offset[d] + u[d] * s, limit[d]);
}

void EmissionGuide::learn(std::span<const uint64_t> worth, int64_t photons) {
    const double n = static_cast<double>(photons);
    double total = 0;
    for (uint64_t w : worth) total += static_cast<double>(w);
    const double scale = total > 0 ? n / total : 0.0;
    for (size_t c = 0; c < prior_.size(); ++c) {
        emitted_[c] += n * probability(static_cast<uint32_t>(c));
        worth_[c] += static_cast<double>(worth[c]) * scale;
    }
    trained_ = true;
    rebuild();
}

// p_c = d prior_c + (1 - d) prior_c u_c / sum(prior u), with u_c = worth_c / emitted_c what
// a photon of cell c is worth on average (0 for a cell no photon left yet).
void EmissionGuide::rebuild() {
    const size_t n = prior_.size();
    double learned = 0;
    for (size_t c = 0; c < n; ++c) learned += usefulness(c);
    std::vector<double> p(n);
    for (size_t c = 0; c < n; ++c)
        p[c] = learned > 0 ? kDefensive * prior_[c] + (1 - kDefensive) * usefulness(c) / learned : prior_[c];
    const std::vector<uint32_t> units = toUnits(p);
    upper_.resize(n);
    weight_.resize(n);
    uint32_t running = 0;
    for (size_t c = 0; c < n; ++c) {
        running += units[c];
        upper_[c] = running;
    }
    for (size_t c = 0; c < n; ++c) {
        const double probability = this->probability(static_cast<uint32_t>(c));
        weight_[c] = probability > 0 ? static_cast<float>(prior_[c] / probability) : 0.0f;
    }
}

double EmissionGuide::usefulness(size_t c) const {
    return emitted_[c] > 0 ? prior_[c] * worth_[c] / emitted_[c] : 0.0;
}

// Probabilities in whole units of 2^-24 summing to 2^24: each rounded down, the units left
// handed to the largest remainders (each cell is then within a unit of its p), and every
// cell with p > 0 given at least one unit (taken back from the largest cells), so no place
// the plain emission reaches is ever left out.
std::vector<uint32_t> EmissionGuide::toUnits(const std::vector<double>& p) {
    const size_t n = p.size();
    std::vector<uint32_t> units(n);
    std::vector<double> remainder(n);
    int64_t total = 0;
    for (size_t c = 0; c < n; ++c) {
        const double exact = p[c] * kUnits;
        units[c] = static_cast<uint32_t>(std::floor(exact));
        remainder[c] = exact - units[c];
        if (p[c] > 0 && units[c] == 0) units[c] = 1, remainder[c] = -1;
        total += units[c];
    }
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    if (total < kUnits) {
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return remainder[a] > remainder[b]; });
        for (size_t k = 0; total < kUnits; k = (k + 1) % n) ++units[order[k]], ++total;
    } else if (total > kUnits) {
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return units[a] > units[b]; });
        for (size_t k = 0; total > kUnits; k = (k + 1) % n)
            if (units[order[k]] > 1) --units[order[k]], --total;
    }
    return units;
}

}  // namespace photon
