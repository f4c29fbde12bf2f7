// A spatial hash grid over spheres (visible points and their gather radii), rebuilt each
// pass. Each sphere is entered in every cell its bounding box overlaps, so a photon looks
// in one cell only (Hachisuka & Jensen 2009, sec. 4.2). The cell size is three times the
// mean radius, which measured fastest overall (fewer entries to build than with twice the
// radius, for a few more candidates per photon), or the largest radius if that is wider,
// which bounds the entries per sphere.
#include <cstdint>
#include <vector>
#include "../math/vec.h"

#pragma once

namespace photon {

class HashGrid {
public:
    // Builds over `count` spheres; center(i) and radiusSquared(i) are read through the
    // callables. Spheres with radius <= 0 are left out.
    template <class CenterFn, class RadiusSquaredFn>
    void build(size_t count, CenterFn center, RadiusSquaredFn radiusSquared);

    // Photons look up their bucket in three steps so that callers can work on many at once
    // and prefetch each step's memory before the next needs it.
    static constexpr uint32_t kNoBucket = ~0u;
    // The bucket of the cell holding p, or kNoBucket outside the grid.
    uint32_t bucketOf(Vec3 p) const {
        int ix, iy, iz;
        return cellOf(p, ix, iy, iz) ? hash(ix, iy, iz) : kNoBucket;
    }
    void prefetchBucket(uint32_t h) const { __builtin_prefetch(&offsets_[h]); }
    struct Sphere {
        Vec3 center;
        float radiusSquared;
    };
    // The spheres entered in bucket h, with their indices: a superset of those containing
    // any point of its cells (callers test the distance).
    struct Span {
        const Sphere* spheres = nullptr;
        const uint32_t* indices = nullptr;
        uint32_t size = 0;
    };
    Span bucket(uint32_t h) const {
        return {spheres_.data() + offsets_[h], indices_.data() + offsets_[h], offsets_[h + 1] - offsets_[h]};
    }

    size_t entryCount() const { return indices_.size(); }
    size_t bytes() const {
        return (offsets_.capacity() + indices_.capacity() + firstKey_.capacity()) * sizeof(uint32_t) +
               spheres_.capacity() * sizeof(Sphere) + (keys_.capacity() + sortScratch_.capacity()) * sizeof(uint64_t);
    }

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
    void setup(size_t count, Vec3 lo, Vec3 hi, float meanRadius, float maxRadius);
    void countAndFill(size_t count, const std::vector<Vec3>& centers, const std::vector<float>& radiiSquared);

    Vec3 origin_;
    float invCellSize_ = 1;
    int resolution_[3] = {1, 1, 1};
    uint32_t mask_ = 0;
    std::vector<uint32_t> offsets_;  // bucket h holds entries [offsets_[h], offsets_[h+1])
    std::vector<Sphere> spheres_;    // by entry
    std::vector<uint32_t> indices_;  // by entry: the sphere's index
    // Build scratch, kept between passes: each sphere's first key, the (bucket, sphere) keys.
    std::vector<uint32_t> firstKey_;
    std::vector<uint64_t> keys_, sortScratch_;
};

}  // namespace photon

#include "hash_grid_build.h"
