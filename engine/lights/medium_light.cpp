// A medium that emits, as a light: sigma_a(p) Le(p) per unit volume and solid angle, the
// same in every direction (description/medium_emission.h), so a photon leaves a point p drawn
// with density pdf(p) in a uniform direction with flux 4 pi sigma_a(p) Le(p) / pdf(p).
//
// Points are drawn over the cells of the grid that says where it emits
// (MediumDescription::emissionRegion; for a homogeneous medium one of 16^3 cells over the
// shapes it is inside of, Scene::buildLights), each the unit cube of lattice space around one
// sample, which together fill the grid's box (the medium is dark outside it), and a point
// outside the shapes that bound the medium emits nothing (its photon is spent): a cell in
// proportion to the mean over channels of what it emits at its centre, uniformly within
// it. A cell's light is not zero wherever any of the 27 samples its interpolation reads is
// (above the blackbody's cut-off, for a temperature grid), so every such cell is kept with
// at least a hundredth of the mean cell's weight: the density stays above zero wherever the
// emission may be, which keeps the estimate unbiased where a centre misses a wisp.
//
// No light sample is taken toward it: from a point inside, 1 / r^2 would make the
// estimate's variance unbounded. Paths count its light where they cross it
// (sampleEmissionAlong), and SPPM's photons bring its direct light to visible points.
#include <algorithm>
#include <bit>
#include <cmath>
#include <tbb/parallel_for.h>
#include "lights/light_factories.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace photon {
namespace {

// Each sample's largest neighbour within one step on every axis (its own included): the
// 27 samples a cell around it interpolates between. In place, one axis at a time.
void dilateByOne(std::vector<float>& v, const int n[3]) {
    const size_t stride[3] = {1, size_t(n[0]), size_t(n[0]) * n[1]};
    std::vector<float> line;
    for (int a = 0; a < 3; ++a) {
        const size_t count = v.size() / n[a];
        line.resize(n[a]);
        for (size_t l = 0; l < count; ++l) {
            // The l-th line along axis a: its first sample's index.
            const size_t below = l % stride[a], above = l / stride[a];
            const size_t first = above * stride[a] * n[a] + below;
            for (int i = 0; i < n[a]; ++i) line[i] = v[first + i * stride[a]];
            for (int i = 0; i < n[a]; ++i) {
                float m = line[i];
                if (i > 0) m = std::max(m, line[i - 1]);
                if (i + 1 < n[a]) m = std::max(m, line[i + 1]);
                v[first + i * stride[a]] = m;
            }
        }
    }
}

class MediumLight final : public Light {
public:
    MediumLight(const MediumDescription& m, std::shared_ptr<const DensityGrid> region, std::function<bool(Vec3)> contains)
        : medium_(m), region_(std::move(region)), contains_(std::move(contains)) {
        const DensityGrid& grid = *region_;
        n_[0] = grid.nx(), n_[1] = grid.ny(), n_[2] = grid.nz();
        worldFromLattice_ = grid.latticeFromWorld().inverse();
        cellVolume_ = std::abs(worldFromLattice_.determinant());
        // Where the region's samples allow light at all: above the blackbody's cut-off on a
        // temperature grid (MediumEmission::atTemperature), above zero on any other.
        const MediumEmission& e = *m.emission;
        const float threshold =
            m.emission->temperature ? e.temperatureOffset + 100.0f / e.temperatureScale : 0.0f;
        const size_t count = size_t(n_[0]) * n_[1] * n_[2];
        std::vector<float> reach(count);
        tbb::parallel_for(0, n_[2], [&](int k) {
            for (int j = 0; j < n_[1]; ++j)
                for (int i = 0; i < n_[0]; ++i) reach[index(i, j, k)] = grid.sample(i, j, k);
        });
        dilateByOne(reach, n_);
        // What each cell emits at its centre (mean over channels), and the power it stands for.
        std::vector<float> weight(count, 0.0f);
        std::vector<Color> slicePower(n_[2], Color(0.0f));
        tbb::parallel_for(0, n_[2], [&](int k) {
            double sum[3] = {0, 0, 0};
            for (int j = 0; j < n_[1]; ++j)
                for (int i = 0; i < n_[0]; ++i) {
                    const size_t c = index(i, j, k);
                    if (!(reach[c] > threshold)) {
                        weight[c] = -1;  // dark throughout
                        continue;
                    }
                    const Color emitted = emittedAt(worldFromLattice_.point(Vec3(float(i), float(j), float(k))));
                    weight[c] = average(emitted);
                    for (int ch = 0; ch < 3; ++ch) sum[ch] += emitted[ch];
                }
            slicePower[k] = Color(float(sum[0]), float(sum[1]), float(sum[2]));
        });
        double mean = 0;
        size_t possible = 0;
        for (float w : weight)
            if (w >= 0) mean += w, ++possible;
        for (const Color& p : slicePower) power_ += p;
        power_ *= 4.0f * kPi * cellVolume_;
        if (possible == 0) return;
        mean /= double(possible);
        const float floor = static_cast<float>(mean > 0 ? 0.01 * mean : 1.0);
        double total = 0;
        for (size_t c = 0; c < count; ++c) {
            if (weight[c] < 0) continue;
            total += std::max(weight[c], floor);
            cells_.push_back(static_cast<uint32_t>(c));
            cdf_.push_back(total);
        }
        for (double& s : cdf_) s /= total;
        cdf_.back() = 1.0;
        // The box of the lattice's cells in the world, for the light's bounds.
        lo_ = Vec3(std::numeric_limits<float>::infinity()), hi_ = -lo_;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 u{corner & 1 ? n_[0] - 0.5f : -0.5f, corner & 2 ? n_[1] - 0.5f : -0.5f,
                         corner & 4 ? n_[2] - 0.5f : -0.5f};
            const Vec3 w = worldFromLattice_.point(u);
            lo_ = vmin(lo_, w), hi_ = vmax(hi_, w);
        }
    }

    Color power() const override { return power_; }
    bool sampledDirectly() const override { return false; }
    std::optional<LightSample> sampleIncident(Vec3, Vec3, Vec2) const override { return std::nullopt; }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        if (cells_.empty()) return std::nullopt;
        const size_t k = std::min(size_t(std::upper_bound(cdf_.begin(), cdf_.end(), double(uPosition.x)) - cdf_.begin()),
                                  cells_.size() - 1);
        const uint32_t c = cells_[k];
        const int i = int(c % uint32_t(n_[0])), j = int(c / uint32_t(n_[0]) % uint32_t(n_[1])),
                  kz = int(c / (uint32_t(n_[0]) * uint32_t(n_[1])));
        // The point within the cell: three numbers from the photon's own (the cell's pick
        // leaves too few bits of uPosition.x), mixed into independent ones.
        const uint64_t h = mix64<uint64_t>(uint64_t(std::bit_cast<uint32_t>(uPosition.x)) << 32 ^
                                           std::bit_cast<uint32_t>(uPosition.y) ^
                                           uint64_t(std::bit_cast<uint32_t>(uDirection.x)) << 17 ^
                                           uint64_t(std::bit_cast<uint32_t>(uDirection.y)) << 41);
        const float fx = float(h & 0x1fffff) * 0x1p-21f, fy = float((h >> 21) & 0x1fffff) * 0x1p-21f,
                    fz = float((h >> 42) & 0x1fffff) * 0x1p-21f;
        const Vec3 p = worldFromLattice_.point(Vec3(float(i) - 0.5f + fx, float(j) - 0.5f + fy, float(kz) - 0.5f + fz));
        const double cellProbability = cdf_[k] - (k > 0 ? cdf_[k - 1] : 0.0);
        const float pdf = static_cast<float>(cellProbability / cellVolume_);
        const Color emitted = emittedAt(p);
        if (!(pdf > 0) || isBlack(emitted) || !contains_(p)) return std::nullopt;
        return PhotonEmission{p, sampleUniformSphere(uDirection), emitted * (4.0f * kPi / pdf), Vec3{}};
    }

    std::optional<LightBounds> bounds() const override {
        LightBounds b;
        b.lo = lo_, b.hi = hi_;
        b.intensity = average(power_) / (4.0f * kPi);
        return b;  // every direction (cosThetaO -1)
    }

private:
    size_t index(int i, int j, int k) const { return (size_t(k) * n_[1] + j) * n_[0] + i; }
    // sigma_a(p) Le(p): light emitted per unit volume and solid angle.
    Color emittedAt(Vec3 p) const { return medium_.absorption * medium_.densityAt(p) * medium_.emission->at(p); }

    const MediumDescription& medium_;
    std::shared_ptr<const DensityGrid> region_;
    std::function<bool(Vec3)> contains_;
    int n_[3];
    Transform worldFromLattice_;
    float cellVolume_ = 0;
    Color power_{0.0f};
    std::vector<uint32_t> cells_;  // the cells that may emit, by index
    std::vector<double> cdf_;      // their weights' running sum over the total
    Vec3 lo_, hi_;
};

}  // namespace

std::unique_ptr<Light> makeMediumLight(const MediumDescription& medium, std::shared_ptr<const DensityGrid> region,
                                       std::function<bool(Vec3)> contains) {
    if (!medium.emits() || !region) throw std::invalid_argument("medium \"" + medium.name + "\" emits no light a grid bounds");
    if (double(region->nx()) * region->ny() * region->nz() > double(UINT32_MAX))
        throw std::invalid_argument("medium \"" + medium.name + "\": its emission grid has more than 2^32 cells");
    return std::make_unique<MediumLight>(medium, std::move(region), std::move(contains));
}

}  // namespace photon
