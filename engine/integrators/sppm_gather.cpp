// Adding a batch of photon hits to the visible points around them. The lookups form a
// chain of dependent loads (grid bucket -> entries -> discs -> visible point), each likely
// a cache miss; walking the whole batch one step at a time, with a prefetch for the next
// step, keeps many misses in flight instead of one.
#include <atomic>
#include "photon_kernel.h"
#include "sppm_gather_batch.h"

namespace photon {

namespace {

struct Candidate {
    uint32_t hit, point;
    float d2;  // squared distance from the hit to the point
};

// Per-thread scratch for the candidates inside their discs: no allocation per batch.
std::vector<Candidate>& gatherScratch() {
    thread_local std::vector<Candidate> scratch;
    return scratch;
}

}  // namespace

void SppmIntegrator::gather(GatherBatch& batch, PhotonCounters& counters) {
    const size_t n = batch.size();
    std::array<HashGrid::Span, GatherBatch::kCapacity> spans{};
    std::array<uint32_t, GatherBatch::kCapacity> buckets;
    for (size_t i = 0; i < n; ++i) {
        buckets[i] = grid_.bucketOf(batch[i].p);
        if (buckets[i] != HashGrid::kNoBucket) grid_.prefetchBucket(buckets[i]);
    }
    for (size_t i = 0; i < n; ++i) {
        if (buckets[i] == HashGrid::kNoBucket) continue;
        spans[i] = grid_.bucket(buckets[i]);
        __builtin_prefetch(spans[i].begin);
    }
    for (size_t i = 0; i < n; ++i)
        for (const uint32_t* e = spans[i].begin; e != spans[i].end; ++e) __builtin_prefetch(&discs_[*e]);

    // Distance tests, written without a branch on the outcome (about one candidate in ten is
    // inside its disc, at random, which a branch predictor cannot learn): every candidate is
    // written and the end of the list moves on only for those inside.
    size_t total = 0;
    for (size_t i = 0; i < n; ++i) total += static_cast<size_t>(spans[i].end - spans[i].begin);
    counters.candidates += static_cast<int64_t>(total);
    std::vector<Candidate>& inside = gatherScratch();
    if (inside.size() < total) inside.resize(total);
    size_t count = 0;
    for (size_t i = 0; i < n; ++i)
        for (const uint32_t* e = spans[i].begin; e != spans[i].end; ++e) {
            const GatherDisc& disc = discs_[*e];
            float d2 = lengthSquared(disc.p - batch[i].p);
            inside[count] = {static_cast<uint32_t>(i), *e, d2};
            count += d2 <= disc.r2;
        }
    for (size_t c = 0; c < count; ++c) __builtin_prefetch(&visible_[inside[c].point], 1);
    // The kernel's d^2 / r^2 only for the one candidate in ten that is inside.
    for (size_t c = 0; c < count; ++c)
        addPhoton(batch[inside[c].hit], inside[c].point, inside[c].d2 / discs_[inside[c].point].r2, counters);
    batch.clear();
}

void SppmIntegrator::addPhoton(const PhotonHit& hit, uint32_t point, float d2OverR2, PhotonCounters& counters) {
    VisiblePoint& vp = visible_[point];
    Vec3 vn = vp.n.decode();
    // Photons on surfaces facing elsewhere (across a corner, the back of a thin wall)
    // do not belong to this point's disc.
    if (dot(vn, hit.n) < 0.5f) return;
    Color c;
    if (vp.lambertian) {  // f = tint / pi above the surface, already in beta
        if (!(dot(vn, hit.wi) > 0)) return;
        c = vp.beta;
    } else {
        Frame frame = Frame::fromNormal(vn);
        Color f = scene_->materialAt(vp.material).eval(vp.woLocal.decode(), frame.toLocal(hit.wi), vp.tint,
                                                       TransportMode::Radiance, vp.lobes);
        if (isBlack(f)) return;
        c = vp.beta * f;
    }
    ++counters.accepted;
    c *= hit.flux * kernelWeight(settings_.kernel, d2OverR2);
    for (int k = 0; k < 3; ++k) {
        // Scaling by a power of two is exact in float as in double, and the units fit a
        // signed 64-bit integer: one conversion instruction, not the unsigned one's branches.
        float v = c[k] * static_cast<float>(kFluxScale);
        if (!(v >= 1.0f)) continue;  // also drops NaN
        auto units = static_cast<uint64_t>(static_cast<int64_t>(std::min(v, 0x1p62f)));
        std::atomic_ref<uint64_t>(vp.flux[k]).fetch_add(units, std::memory_order_relaxed);
    }
    std::atomic_ref<uint32_t>(vp.photonCount).fetch_add(1, std::memory_order_relaxed);
}

}  // namespace photon
