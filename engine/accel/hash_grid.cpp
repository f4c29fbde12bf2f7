

#include "hash_grid.h"
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>

namespace photon {

namespace {
struct Extent {
    Vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    double radiusSum = 0;
    size_t withRadius = 0;
};
}  // namespace

bool HashGrid::cellOf(Vec3 p, int& ix, int& iy, int& iz) const {
    Vec3 g = (p - origin_) * invCellSize_;
    if (!(g.x >= 0 && g.y >= 0 && g.z >= 0)) return false;
    ix = static_cast<int>(g.x);
    iy = static_cast<int>(g.y);
    iz = static_cast<int>(g.z);
    return ix < resolution_[0] && iy < resolution_[1] && iz < resolution_[2];
}

HashGrid::CellRange HashGrid::cellsOverlapping(Vec3 c, float r) const {
    CellRange range;
    for (int a = 0; a < 3; ++a) {
        range.lo[a] = std::clamp(static_cast<int>((c[a] - r - origin_[a]) * invCellSize_), 0, resolution_[a] - 1);
        range.hi[a] = std::clamp(static_cast<int>((c[a] + r - origin_[a]) * invCellSize_), 0, resolution_[a] - 1);
    }
    return range;
}

void HashGrid::setup(size_t count, Vec3 lo, Vec3 hi, double radiusSum, size_t withRadius) {
    float meanRadius = withRadius ? static_cast<float>(radiusSum / static_cast<double>(withRadius)) : 1.0f;
    float cellSize = std::max(3.0f * meanRadius, 1e-6f);
    invCellSize_ = 1.0f / cellSize;
    origin_ = lo;
    for (int a = 0; a < 3; ++a)
        resolution_[a] = std::clamp(static_cast<int>((hi[a] - lo[a]) * invCellSize_) + 1, 1, 1 << 30);
    // One bucket per sphere: a table that stays in L2 builds and looks up faster than a sparser
    // one, for ~15% more candidates from cells sharing a bucket (photon-bench, 1x vs 4x).
    uint32_t buckets = std::bit_ceil(static_cast<uint32_t>(std::max<size_t>(count, 1024)));
    mask_ = buckets - 1;
    offsets_.assign(buckets + 1, 0);
}

void HashGrid::countAndFill(size_t count, const std::vector<Vec3>& centers, const std::vector<float>& radiiSquared) {
    std::vector<float> radii(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) { radii[i] = radiiSquared[i] > 0 ? std::sqrt(radiiSquared[i]) : 0.0f; });
    Extent e = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, count), Extent{},
        [&](const tbb::blocked_range<size_t>& r, Extent acc) {
            for (size_t i = r.begin(); i < r.end(); ++i) {
                if (!(radii[i] > 0)) continue;
                acc.lo = vmin(acc.lo, centers[i] - Vec3(radii[i]));
                acc.hi = vmax(acc.hi, centers[i] + Vec3(radii[i]));
                acc.radiusSum += radii[i];
                ++acc.withRadius;
            }
            return acc;
        },
        [](Extent a, const Extent& b) {
            a.lo = vmin(a.lo, b.lo);
            a.hi = vmax(a.hi, b.hi);
            a.radiusSum += b.radiusSum;
            a.withRadius += b.withRadius;
            return a;
        });
    if (e.withRadius == 0) e.lo = e.hi = Vec3(0.0f);
    setup(count, e.lo, e.hi, e.radiusSum, e.withRadius);

    // Counting sort into buckets: count entries per bucket, prefix-sum, then fill. The
    // order inside a bucket varies with threads; callers accumulate order-independently.
    auto forEachCell = [&](size_t i, auto&& fn) {
        CellRange cr = cellsOverlapping(centers[i], radii[i]);
        for (int z = cr.lo[2]; z <= cr.hi[2]; ++z)
            for (int y = cr.lo[1]; y <= cr.hi[1]; ++y)
                for (int x = cr.lo[0]; x <= cr.hi[0]; ++x) fn(hash(x, y, z));
    };
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        if (radii[i] > 0)
            forEachCell(i, [&](uint32_t h) { std::atomic_ref<uint32_t>(offsets_[h + 1]).fetch_add(1, std::memory_order_relaxed); });
    });
    for (size_t h = 1; h < offsets_.size(); ++h) offsets_[h] += offsets_[h - 1];
    spheres_.resize(offsets_.back());
    indices_.resize(offsets_.back());
    std::vector<uint32_t> cursor(offsets_.begin(), offsets_.end() - 1);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        if (radii[i] > 0)
            forEachCell(i, [&](uint32_t h) {
                uint32_t slot = std::atomic_ref<uint32_t>(cursor[h]).fetch_add(1, std::memory_order_relaxed);
                indices_[slot] = static_cast<uint32_t>(i);
            });
    });
    // The spheres' copies in entry order: written in sequence, their reads in bucket order
    // can all be in flight at once (writing them with the indices' scattered stores took
    // a third longer).
    tbb::parallel_for(tbb::blocked_range<size_t>(0, indices_.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k < r.end(); ++k) spheres_[k] = {centers[indices_[k]], radiiSquared[indices_[k]]};
    });
}

}  // namespace photon
