// A spatial hash grid over spheres (visible points and their gather radii), rebuilt each
// pass. Each sphere is entered in every cell its bounding box overlaps, so a photon looks
// in one cell only (Hachisuka & Jensen 2009, sec. 4.2), one on each level of the grid.
// Level 0's cells are three mean radii wide, which measured fastest overall (fewer entries
// to build than with twice the radius, for a few more candidates per photon); each level
// above has cells four times wider, and a sphere goes on the lowest level whose cells are
// at least as wide as its radius, so it enters at most three cells along an axis however
// widely radii spread. (On a floor receding to the horizon radii grow with distance: with
// one level of mean-radius cells its far points entered hundreds of cells each, and with
// cells as wide as the largest radius the near ones crowded into a few.) Most scenes need
// level 0 alone.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>
#include <photon/vec.h>

#pragma once

namespace photon {

class HashGrid {
public:
    struct Sphere {
        Vec3 center;
        float radiusSquared;
    };
    // Builds over the spheres, read where they are (a caller keeps its own array of them:
    // no copy of centres and radii during the build, 20 bytes a sphere at a frame's peak).
    // Spheres with radius <= 0 are left out.
    void build(std::span<const Sphere> spheres);
    // Frees the grid and its build buffers (kept between builds so that the next one does
    // not fault their pages in again); the grid is empty until built again.
    void release();

    // Photons look up their buckets in three steps so that callers can work on many at
    // once and prefetch each step's memory before the next needs it.
    static constexpr uint32_t kNoBucket = ~0u;
    // The levels that hold spheres: a photon looks in one bucket on each (once in a bucket
    // that two levels share).
    int levelCount() const { return static_cast<int>(levels_.size()); }
    // The bucket of the cell holding p on a level (0 to levelCount() - 1), or kNoBucket
    // outside the grid.
    uint32_t bucketOf(Vec3 p, int level) const {
        const Level& l = levels_[level];
        int ix, iy, iz;
        return cellOf(p, l, ix, iy, iz) ? hash(ix, iy, iz, l.id) : kNoBucket;
    }
    // What bucket(h) reads first, for callers to prefetch (into the cache level they choose).
    const void* bucketAddress(uint32_t h) const { return &offsets_[h]; }
    // The spheres entered in bucket h, with their entries: a superset of those containing
    // any point of its cells on the level looked up (callers test the distance, and the
    // level: a bucket also holds other cells', of any level). A sphere entered twice in one
    // bucket (two of its cells hashed alike) has a negative radiusSquared the second time,
    // so that it holds no point there.
    struct Span {
        const Sphere* spheres = nullptr;
        const uint32_t* entries = nullptr;
        uint32_t size = 0;
    };
    Span bucket(uint32_t h) const {
        return {spheres_ + offsets_[h], entries_.data() + offsets_[h], offsets_[h + 1] - offsets_[h]};
    }
    // An entry is its sphere's index and, in the top bits, its level (16384^2 pixels fit).
    static constexpr int kSphereBits = 28;
    static uint32_t sphereOf(uint32_t entry) { return entry & ((1u << kSphereBits) - 1); }
    static uint32_t levelOf(uint32_t entry) { return entry >> kSphereBits; }

    size_t entryCount() const { return entries_.size(); }
    size_t bytes() const {
        return (offsets_.capacity() + entries_.capacity() + firstKey_.capacity()) * sizeof(uint32_t) +
               arenaEntries_ * kArenaBytesPerEntry;
    }

private:
    static constexpr int kMaxLevels = 16;
    struct Level {
        uint32_t id;  // cells 4^id times level 0's
        float invCellSize;
        int resolution[3];
    };
    struct CellRange {
        int lo[3], hi[3];
    };
    bool cellOf(Vec3 p, const Level& l, int& ix, int& iy, int& iz) const;
    CellRange cellsOverlapping(Vec3 c, float r, const Level& l) const;
    uint32_t hash(int ix, int iy, int iz, uint32_t levelId) const {
        // Teschner et al. 2003 spatial hash, with the level as a fourth coordinate.
        return ((static_cast<uint32_t>(ix) * 73856093u) ^ (static_cast<uint32_t>(iy) * 19349663u) ^
                (static_cast<uint32_t>(iz) * 83492791u) ^ (levelId * 2654435761u)) & mask_;
    }
    void setLevels(std::span<const Sphere> spheres, Vec3 lo, Vec3 hi, float baseCellSize);

    Vec3 origin_;
    std::vector<Level> levels_;       // the levels that hold spheres, finest first
    std::vector<uint8_t> sphereLevel_;    // by sphere: its index in levels_ (build scratch)
    uint32_t mask_ = 0;
    std::vector<uint32_t> offsets_;  // bucket h holds entries [offsets_[h], offsets_[h+1])
    std::vector<uint32_t> entries_;  // by entry: the sphere's index and level (sphereOf, levelOf)
    // One buffer of 16 bytes an entry, used twice in a build: first as the radix sort's
    // (bucket, entry) keys and its scratch, 8 bytes an entry each; then, once the entries and
    // offsets are read off the sorted keys, as the spheres by entry. Apart, the three held
    // 32 bytes an entry (~42 bytes a pixel more at a frame's peak, docs/sppm.md#memory).
    static constexpr size_t kArenaBytesPerEntry = 2 * sizeof(uint64_t);
    static_assert(sizeof(Sphere) == kArenaBytesPerEntry);
    std::unique_ptr<std::byte[]> arena_;
    size_t arenaEntries_ = 0;     // the arena's room, in entries
    Sphere* spheres_ = nullptr;   // in the arena once built
    // Build scratch, kept between passes: each sphere's first key.
    std::vector<uint32_t> firstKey_;
};

}  // namespace photon

