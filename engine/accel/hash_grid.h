// A spatial hash grid over spheres (visible points and their gather radii), rebuilt each
// pass. Each sphere is entered in every cell its bounding box overlaps, so a photon looks
// in one cell only (Hachisuka & Jensen 2009, sec. 4.2). The cell size is three times the
// mean radius, which measured fastest overall: fewer entries to build than with twice the
// radius, for a few more candidates per photon.
#include <cstdint>
#include <vector>
#include "../math/vec.h"

#pragma once

namespace photon {

class HashGrid {
public:
    // Builds over `count` spheres; centers[i] and radii[i] are read through the callables.
    // Spheres with radius <= 0 are left out.
    template <class CenterFn, class RadiusFn>
    void build(size_t count, CenterFn center, RadiusFn radius);

    // Photons look up their bucket in three steps so that callers can work on many at once
    // and prefetch each step's memory before the next needs it.
    static constexpr uint32_t kNoBucket = ~0u;
    // The bucket of the cell holding p, or kNoBucket outside the grid.
    uint32_t bucketOf(Vec3 p) const {
        int ix, iy, iz;
        return cellOf(p, ix, iy, iz) ? hash(ix, iy, iz) : kNoBucket;
    }
    void prefetchBucket(uint32_t h) const { __builtin_prefetch(&offsets_[h]); }
    // Indices of the spheres entered in bucket h: a superset of those containing any point
    // of its cells (callers test the distance).
    struct Span {
        const uint32_t *begin = nullptr, *end = nullptr;
    };
    Span bucket(uint32_t h) const { return {entries_.data() + offsets_[h], entries_.data() + offsets_[h + 1]}; }

    size_t entryCount() const { return entries_.size(); }
    size_t bytes() const { return (offsets_.capacity() + entries_.capacity()) * sizeof(uint32_t); }

private:
    struct CellRange {
        int lo[3], hi[3];
    };
    bool cellOf(Vec3 p, int& ix, int& iy, int& iz) const;
    CellRange cellsOverlapping(Vec3 c, float r) const;
    uint32_t hash(int ix, int iy, int iz) const {
        // Teschner et al. 2003 spatial hash.
        return ((static_cast<uint32_t>(ix) * 73856093u) ^ (static_cast<uint32_t>(iy) * 19349663u) ^
                (static_cast<uint32_t>(iz) * 83492791u)) & mask_;
    }
    void setup(size_t count, Vec3 lo, Vec3 hi, double radiusSum, size_t withRadius);
    void countAndFill(size_t count, const std::vector<Vec3>& centers, const std::vector<float>& radii);

    Vec3 origin_;
    float invCellSize_ = 1;
    int resolution_[3] = {1, 1, 1};
    uint32_t mask_ = 0;
    std::vector<uint32_t> offsets_;  // bucket h holds entries_[offsets_[h], offsets_[h+1])
    std::vector<uint32_t> entries_;
};

}  // namespace photon

#include "hash_grid_build.h"
