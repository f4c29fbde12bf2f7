// The gather's steps (sppm_gather_pipeline.h) and what one accepted photon adds.
#include <atomic>
#include "integrators/common/photon_kernel.h"
#include "media/henyey_greenstein.h"
#include "integrators/sppm/sppm_gather_pipeline.h"

namespace photon {

namespace {
// Every prefetch of the gather goes to L2 (prefetcht1), not L1 (prefetcht0): photon-bench,
// 2 threads, on an AMD EPYC (Zen 4) VM whose other tenants leave it about 6 MiB of L3,
// ratio 0.44 -> 0.52. Not for want of room in L1: batches of 8 or 16 hits, whose lines
// fill a fraction of it, were as slow with L1 prefetches (0.44-0.45), and so was the whole
// gather run apart from the walk. Evidently a prefetch into L1 holds one of the core's few
// L1 miss buffers for its whole trip to memory (~200 ns here), and every other load that
// misses L1, the walk's and Embree's included, waits for one; L2 keeps its own.
void prefetchIntoL2(const void* p) { __builtin_prefetch(p, 0, 2); }

// Every cache line of [begin, end).
template <class T>
void prefetchRange(const T* begin, const T* end) {
    constexpr uintptr_t kLine = 64;
    for (uintptr_t a = reinterpret_cast<uintptr_t>(begin) & ~(kLine - 1); a < reinterpret_cast<uintptr_t>(end); a += kLine)
        prefetchIntoL2(reinterpret_cast<const void*>(a));
}
}  // namespace

void SppmIntegrator::GatherPipeline::advance() {
    // Oldest first: the batch after its last step is emptied and fills next.
    addInside(at(3));
    testSpheres(at(2));
    openBuckets(at(1));
    findBuckets(at(0));
    filling_ = (filling_ + 1) % kSlots;
}

void SppmIntegrator::GatherPipeline::findBuckets(Batch& b) {
    const HashGrid& grid = sppm_.grid_;
    b.lookups.clear();
    for (int level = 0; level < grid.levelCount(); ++level)
        for (size_t i = 0; i < b.size; ++i) {
            const uint32_t bucket = grid.bucketOf(b.hits[i].p, level);
            if (bucket == HashGrid::kNoBucket) continue;
            prefetchIntoL2(grid.bucketAddress(bucket));
            b.lookups.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(level), bucket, {}});
        }
}

void SppmIntegrator::GatherPipeline::openBuckets(Batch& b) {
    size_t total = 0;
    for (Lookup& l : b.lookups) {
        l.span = sppm_.grid_.bucket(l.bucket);
        prefetchRange(l.span.spheres, l.span.spheres + l.span.size);
        prefetchRange(l.span.entries, l.span.entries + l.span.size);
        total += l.span.size;
    }
    counters_.candidates += static_cast<int64_t>(total);
    if (b.inside.size() < total) b.inside.resize(total);
}

namespace {
// The distance tests of one batch's lookups, written without a branch on the outcome (about
// one candidate in ten is inside its disc, at random, which a branch predictor cannot
// learn): every candidate is written and the end of the list moves on only for those
// inside. With several levels, entries of other levels share a bucket but not the cell
// looked up; with one there are none to skip.
template <bool kLevels, class Lookup, class Hit, class Candidate>
size_t testLookups(const std::vector<Lookup>& lookups, const Hit& hits, std::vector<Candidate>& inside) {
    size_t count = 0;
    for (const Lookup& l : lookups) {
        const Vec3 p = hits[l.hit].p;
        for (uint32_t k = 0; k < l.span.size; ++k) {
            const HashGrid::Sphere& sphere = l.span.spheres[k];
            const uint32_t entry = l.span.entries[k];
            float d2 = lengthSquared(sphere.center - p);
            inside[count] = {l.hit, HashGrid::sphereOf(entry), d2, sphere.radiusSquared};
            bool in = d2 <= sphere.radiusSquared;
            if constexpr (kLevels) in &= HashGrid::levelOf(entry) == l.level;
            count += in;
        }
    }
    return count;
}
}  // namespace

void SppmIntegrator::GatherPipeline::testSpheres(Batch& b) {
    const size_t count = sppm_.grid_.levelCount() > 1 ? testLookups<true>(b.lookups, b.hits, b.inside)
                                                      : testLookups<false>(b.lookups, b.hits, b.inside);
    b.insideCount = count;
    for (size_t c = 0; c < count; ++c) prefetchIntoL2(&sppm_.visible_[b.inside[c].point]);
}

void SppmIntegrator::GatherPipeline::addInside(Batch& b) {
    // The kernel's d^2 / r^2 only for the one candidate in ten that is inside.
    for (size_t c = 0; c < b.insideCount; ++c) {
        const Candidate& k = b.inside[c];
        sppm_.addPhoton(b.hits[k.hit], k.point, k.d2 / k.r2, counters_);
    }
    b.size = 0;
    b.insideCount = 0;
}

void SppmIntegrator::addPhoton(const PhotonHit& hit, uint32_t point, float d2OverR2, PhotonCounters& counters) {
    VisiblePoint& vp = visible_[point];
    Color c;
    float kernel;
    if (vp.inMedium) [[unlikely]] {
        // Photons that scattered in a medium (no normal) go to the points in it; the facing
        // test below turns them away from surfaces.
        if (hit.n != Vec3{}) return;
        const MediumDescription& m = scene_->medium(vp.material);
        c = vp.beta * henyeyGreenstein(dot(vp.n.decode(), hit.wi), m.g);
        // Where the density varies, each photon counts over the density where it scattered
        // (the point's beta is over the medium's sigma_s alone): the ball then averages the
        // in-scattered radiance, which varies smoothly, not sigma_s L, which changes with
        // the density from sample to sample (storeVolumePoint).
        if (m.density) [[unlikely]] {
            const float density = m.densityAt(hit.p);
            if (!(density > 0)) return;
            c /= density;
        }
        kernel = kernelWeight(settings_.kernel, d2OverR2, KernelDomain::Ball);
    } else {
        Vec3 vn = vp.n.decode();
        // Photons on surfaces facing elsewhere (across a corner, the back of a thin wall)
        // do not belong to this point's disc; but the far side of a sheet that transmits is
        // the same surface, its normal turned toward the photon.
        float facing = dot(vn, hit.n);
        if (vp.transmits) facing = std::abs(facing);
        if (facing < 0.5f) [[unlikely]] {
            // A surface facing elsewhere inside the disc's sphere is a corner or an edge the
            // disc reaches past, where it counts area with no photons: such a photon counts
            // toward the spread as one at the rim, which reads as the light curving there
            // and shrinks the radius (adaptive_radius.h). Not a photon that scattered in a
            // medium (no normal), nor in the guide's training passes, nor where radii follow
            // alpha's schedule alone (the spread is then never read).
            // With the disc's coverage measured (render.disc_coverage) the estimate no longer
            // counts that area: the photon marks the disc for a full measurement instead.
            if (coversDiscs_) {
                if (hit.n != Vec3{}) std::atomic_ref<uint8_t>(edgeSeen_[point]).store(1, std::memory_order_relaxed);
            } else if (adaptsRadius_ && !counters.guideWorth && hit.n != Vec3{})
                std::atomic_ref<uint64_t>(vp.gathered)
                    .fetch_add(static_cast<uint64_t>(PhotonSpread::kUnitsPerPhoton) << 32, std::memory_order_relaxed);
            return;
        }
        if (vp.lambertian) {  // f = tint / pi above the surface, already in beta
            if (!(dot(vn, hit.wi) > 0)) return;
            c = vp.beta;
        } else {
            Frame frame = Frame::fromNormal(vn);
            const Material& m = scene_->materialAt(vp.material);
            Color f =
                m.eval(vp.woLocal.decode(), frame.toLocal(hit.wi), m.inputsAt({vp.uv, discs_[point].center, vn}), TransportMode::Radiance, vp.lobes);
            if (isBlack(f)) return;
            c = vp.beta * f;
        }
        kernel = kernelWeight(settings_.kernel, d2OverR2);
    }
    ++counters.accepted;
    // The photon, and its d^2 / r^2 for render.adaptive_radius (rounded to the nearest unit),
    // but not in the guide's training passes, whose points keep their guide weight there.
    uint64_t gathered = 1;
    if (counters.guideWorth) counters.guideWorth[hit.cell] += vp.high();
    else gathered |= static_cast<uint64_t>(d2OverR2 * PhotonSpread::kUnitsPerPhoton + 0.5f) << 32;
    c *= hit.flux * kernel;
    for (int k = 0; k < 3; ++k) {
        // Scaling by a power of two is exact in float as in double, and the units fit a
        // signed 64-bit integer: one conversion instruction, not the unsigned one's branches.
        float v = c[k] * static_cast<float>(kFluxScale);
        if (!(v >= 1.0f)) continue;  // also drops NaN
        auto units = static_cast<uint64_t>(static_cast<int64_t>(std::min(v, 0x1p62f)));
        std::atomic_ref<uint64_t>(vp.flux[k]).fetch_add(units, std::memory_order_relaxed);
    }
    std::atomic_ref<uint64_t>(vp.gathered).fetch_add(gathered, std::memory_order_relaxed);
}

}  // namespace photon
