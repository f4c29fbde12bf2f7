// Photon hits on their way into the visible points around them. Finding those points is a
// chain of dependent loads (grid bucket -> its entries -> the visible points inside), each
// likely a cache miss. Hits wait in batches, and each batch takes one step of the chain
// whenever a new batch fills, after prefetching the memory of its next step, so that a
// prefetch has a whole batch's worth of photon walking to arrive. When one batch ran every
// step back to back, loading a bucket's entries took a third of the gather's time. The
// prefetches go to L2, not L1 (sppm_gather.cpp says why). What is left is bound by how
// many cache lines the gather touches, which is why the grid's entries carry their spheres
// (accel/hash_grid.h).
#pragma once
#include <array>
#include <vector>
#include "integrators/sppm/sppm.h"

namespace photon {

class SppmIntegrator::GatherPipeline {
public:
    GatherPipeline(SppmIntegrator& sppm, PhotonCounters& counters) : sppm_(sppm), counters_(counters) {}
    GatherPipeline(const GatherPipeline&) = delete;
    GatherPipeline& operator=(const GatherPipeline&) = delete;

    void push(const PhotonHit& hit) {
        Batch& b = batches_[filling_];
        b.hits[b.size++] = hit;
        if (b.size == kBatchSize) advance();
    }
    // Every waiting hit into its visible points.
    void flush() {
        for (int s = 0; s < kSlots; ++s) advance();
    }

private:
    static constexpr size_t kBatchSize = 64;
    struct Candidate {
        uint32_t hit, point;
        float d2, r2;  // squared distance from the hit to the point, squared radius
    };
    // One bucket to look in for a hit: one per level of the grid (most scenes have one).
    struct Lookup {
        uint32_t hit, level, bucket;
        HashGrid::Span span;
    };
    struct Batch {
        std::array<PhotonHit, kBatchSize> hits;
        size_t size = 0;
        std::vector<Lookup> lookups;
        std::vector<Candidate> inside;  // candidates inside their disc
        size_t insideCount = 0;
    };
    // A batch is filling (stage 0) or waits after one of the steps below; the last step
    // empties it and it fills again.
    static constexpr int kSlots = 4;
    Batch& at(int stage) { return batches_[(filling_ + kSlots - stage) % kSlots]; }
    void advance();
    void findBuckets(Batch& b);
    void openBuckets(Batch& b);
    void testSpheres(Batch& b);
    void addInside(Batch& b);

    SppmIntegrator& sppm_;
    PhotonCounters& counters_;
    std::array<Batch, kSlots> batches_;
    int filling_ = 0;
};

}  // namespace photon
