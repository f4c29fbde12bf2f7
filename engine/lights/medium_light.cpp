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
        // The box of the lattice's cells in the world, for the light's bounds.
        lo_ = Vec3(std::numeric_limits<float>::infinity()), hi_ = -lo_;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 u{corner & 1 ? n_[0] - 0.5f : -0.5f, corner & 2 ? n_[1] - 0.5f : -0.5f,
                         corner & 4 ? n_[2] - 0.5f : -0.5f};
            const Vec3 w = worldFromLattice_.point(u);
            lo_ = vmin(lo_, w), hi_ = vmax(hi_, w);
        }
        // Slice by slice along z, each cell's bound from the largest corners of the lattice
        // cells it overlaps (cellMaxima), kept for two slices of those at a time: memory in
        // proportion to a slice and the cells that may emit, not to the grid.
        std::vector<float> below, above = cellMaxima(grid, -1);
        double sum[3] = {0, 0, 0}, weights = 0;
        const size_t rowCells = size_t(n_[0]) + 1;
        rowEnd_.reserve(size_t(n_[1]) * n_[2]);
        rowCdf_.reserve(size_t(n_[1]) * n_[2]);
        for (int k = 0; k < n_[2]; ++k) {
            below.swap(above);
            above = cellMaxima(grid, k);
            std::vector<std::vector<std::pair<uint16_t, Color>>> rows(n_[1]);
            tbb::parallel_for(0, n_[1], [&](int j) {
                for (int i = 0; i < n_[0]; ++i) {
                    // Lattice cells i-1 and i, j-1 and j, k-1 and k: index i, j in the slices
                    // (which start at lattice cell -1).
                    float bound = 0;
                    for (const std::vector<float>* slice : {&below, &above})
                        for (int dj = 0; dj < 2; ++dj)
                            for (int di = 0; di < 2; ++di)
                                bound = std::max(bound, (*slice)[size_t(j + dj) * rowCells + size_t(i + di)]);
                    if (!(bound > threshold)) continue;  // dark throughout
                    rows[j].push_back({uint16_t(i), emittedAt(worldFromLattice_.point(Vec3(float(i), float(j), float(k))))});
                }
            });
            // The cells' weights as they are for now; the floor and the running sums below.
            for (const auto& row : rows) {
                for (const auto& [i, emitted] : row) {
                    cellX_.push_back(i);
                    cellCdf_.push_back(average(emitted));
                    weights += average(emitted);
                    for (int ch = 0; ch < 3; ++ch) sum[ch] += emitted[ch];
                }
                rowEnd_.push_back(static_cast<uint32_t>(cellX_.size()));
            }
        }
        power_ = Color(float(sum[0]), float(sum[1]), float(sum[2])) * (4.0f * kPi * cellVolume_);
        if (cellX_.empty()) return;
        const double mean = weights / double(cellX_.size());
        const float floor = static_cast<float>(mean > 0 ? 0.01 * mean : 1.0);
        // Each row's cells by their running sum within it (floats: a row is one line of the
        // grid), the rows by theirs over the grid (doubles: a grid may hold millions).
        double total = 0;
        uint32_t first = 0;
        for (uint32_t end : rowEnd_) {
            double row = 0;
            for (uint32_t c = first; c < end; ++c) row += std::max(cellCdf_[c], floor);
            double running = 0;
            for (uint32_t c = first; c < end; ++c)
                cellCdf_[c] = static_cast<float>((running += std::max(cellCdf_[c], floor)) / row);
            if (end > first) cellCdf_[end - 1] = 1.0f;
            rowCdf_.push_back(total += row);
            first = end;
        }
        for (double& r : rowCdf_) r /= total;
        rowCdf_.back() = 1.0;
    }

    Color power() const override { return power_; }
    bool sampledDirectly() const override { return false; }
    std::optional<LightSample> sampleIncident(Vec3, ReceiverSide, Vec2) const override { return std::nullopt; }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        if (cellX_.empty()) return std::nullopt;
        // The row from both numbers, 48 bits: a grid's rows may be more than 2^24, each
        // less likely than one float number in [0, 1) could pick fairly; then its cell with
        // what is left of them.
        const double u = double(uPosition.x) + double(uPosition.y) * 0x1p-24;
        const size_t row = std::min(size_t(std::upper_bound(rowCdf_.begin(), rowCdf_.end(), u) - rowCdf_.begin()),
                                    rowCdf_.size() - 1);
        const double rowLo = row > 0 ? rowCdf_[row - 1] : 0.0, rowProbability = rowCdf_[row] - rowLo;
        const uint32_t first = row > 0 ? rowEnd_[row - 1] : 0, end = rowEnd_[row];
        if (!(rowProbability > 0) || end == first) return std::nullopt;
        const double v = (u - rowLo) / rowProbability;
        const uint32_t c = std::min(
            uint32_t(std::upper_bound(cellCdf_.begin() + first, cellCdf_.begin() + end, v,
                                      [](double a, float b) { return a < double(b); }) -
                     cellCdf_.begin()),
            end - 1);
        const int i = cellX_[c], j = int(row % size_t(n_[1])), kz = int(row / size_t(n_[1]));
        // The point within the cell: three numbers from the photon's own (the cell's pick
        // leaves too few bits of uPosition), mixed into independent ones.
        const uint64_t h = mix64<uint64_t>(uint64_t(std::bit_cast<uint32_t>(uPosition.x)) << 32 ^
                                           std::bit_cast<uint32_t>(uPosition.y) ^
                                           uint64_t(std::bit_cast<uint32_t>(uDirection.x)) << 17 ^
                                           uint64_t(std::bit_cast<uint32_t>(uDirection.y)) << 41);
        const float fx = float(h & 0x1fffff) * 0x1p-21f, fy = float((h >> 21) & 0x1fffff) * 0x1p-21f,
                    fz = float((h >> 42) & 0x1fffff) * 0x1p-21f;
        const Vec3 p = worldFromLattice_.point(Vec3(float(i) - 0.5f + fx, float(j) - 0.5f + fy, float(kz) - 0.5f + fz));
        const double cellProbability = rowProbability * (double(cellCdf_[c]) - (c > first ? double(cellCdf_[c - 1]) : 0.0));
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
    // The largest corner sample of each lattice cell (i, j, k) of slice k, i in [-1, nx - 1]
    // and j in [-1, ny - 1] (x fastest): a bound on the interpolation within it.
    std::vector<float> cellMaxima(const DensityGrid& grid, int k) const {
        const size_t rowCells = size_t(n_[0]) + 1;
        std::vector<float> maxima(rowCells * (size_t(n_[1]) + 1));
        tbb::parallel_for(-1, n_[1], [&](int j) {
            for (int i = -1; i < n_[0]; ++i) maxima[size_t(j + 1) * rowCells + size_t(i + 1)] = grid.cellMax(i, j, k);
        });
        return maxima;
    }
    // sigma_a(p) Le(p): light emitted per unit volume and solid angle.
    Color emittedAt(Vec3 p) const { return medium_.absorption * medium_.densityAt(p) * medium_.emission->at(p); }

    const MediumDescription& medium_;
    std::shared_ptr<const DensityGrid> region_;
    std::function<bool(Vec3)> contains_;
    int n_[3];
    Transform worldFromLattice_;
    float cellVolume_ = 0;
    Color power_{0.0f};
    // The cells that may emit, row by row (a row: one j and k, in order): each one's i and
    // its weights' running sum within its row over the row's; where each row ends, and the
    // rows' weights' running sum over the total. 6 bytes a cell.
    std::vector<uint16_t> cellX_;
    std::vector<float> cellCdf_;
    std::vector<uint32_t> rowEnd_;
    std::vector<double> rowCdf_;
    Vec3 lo_, hi_;
};

}  // namespace

std::unique_ptr<Light> makeMediumLight(const MediumDescription& medium, std::shared_ptr<const DensityGrid> region,
                                       std::function<bool(Vec3)> contains) {
    if (!medium.emits() || !region) throw std::invalid_argument("medium \"" + medium.name + "\" emits no light a grid bounds");
    if (double(region->nx()) * region->ny() * region->nz() > double(UINT32_MAX) || region->nx() > 65535)
        throw std::invalid_argument("medium \"" + medium.name +
                                    "\": its emission grid has more than 2^32 cells, or rows of more than 65,535");
    return std::make_unique<MediumLight>(medium, std::move(region), std::move(contains));
}

}  // namespace photon
