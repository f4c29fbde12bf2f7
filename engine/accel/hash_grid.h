// A spatial hash grid over spheres (visible points and their gather radii), rebuilt each
// pass. Each sphere is entered in every cell its bounding box overlaps, so a photon looks
// in one cell only (Hachisuka & Jensen 2009, sec. 4.2; cell size three times the mean radius, which measured fastest overall: fewer entries to build than 2x, few more candidates per photon).
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

    // Calls visit(index) for each sphere entered in the cell that holds p (a superset of
    // the spheres containing p: callers test the distance), and prefetch(index) a few
    // entries ahead so the caller's data for them is on its way to the cache.
    template <class Visit, class Prefetch>
    void forEachCandidate(Vec3 p, Visit&& visit, Prefetch&& prefetch_) const {
        int ix, iy, iz;
        if (!cellOf(p, ix, iy, iz)) return;
        uint32_t h = hash(ix, iy, iz);
        uint32_t begin = offsets_[h], end = offsets_[h + 1];
        // Candidates are scattered through the caller's arrays; ask for them early.
        for (uint32_t k = begin; k < end && k < begin + 4; ++k) prefetch_(entries_[k]);
        for (uint32_t k = begin; k < end; ++k) {
            if (k + 4 < end) prefetch_(entries_[k + 4]);
            visit(entries_[k]);
        }
    }

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
