// SPPM photon pass: photons leave the lights in proportion to power, bounce by BSDF
// sampling with Russian roulette, and at every non-delta hit add their flux to the
// visible points whose gather disc holds the hit.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <atomic>
#include "integrators/common/photon_paths.h"
#include "integrators/common/shading.h"
#include "integrators/sppm/sppm_gather_pipeline.h"

namespace photon {

namespace {
constexpr int64_t kPhotonsPerChunk = 1024;

}  // namespace

// Photon arrivals go into the gather pipeline.
class SppmIntegrator::GatheringSink final : public PhotonArrivalSink {
public:
    GatheringSink(SppmIntegrator& sppm, PhotonCounters& counters) : pipeline_(sppm, counters) {}
    void flush() { pipeline_.flush(); }
    void arrive(const PhotonArrival& a) override { pipeline_.push({a.p, a.ns, a.wi, a.flux, a.cell}); }  // ns is 0 in a medium

private:
    GatherPipeline pipeline_;
};

void SppmIntegrator::photonPass(const CancelToken& cancel, int64_t photons) {
    const int64_t total = photons;
    const int64_t chunks = (total + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    const bool teaching = guidePass_ > 0;  // the first training pass only counts photons
    PhotonCounters counters = tbb::parallel_reduce(
        tbb::blocked_range<int64_t>(0, chunks, 1), PhotonCounters{},
        [&](const tbb::blocked_range<int64_t>& r, PhotonCounters acc) {
            PhotonPathSettings paths{settings_.seed, static_cast<uint64_t>(passIndex_), settings_.maxDepth};
            // Direct light may come from light sampling in the camera pass instead.
            paths.firstArrivalDepth = settings_.direct == DirectLighting::Photons ? 0 : 1;
            // But no light sample finds a medium's light: its photons bring its direct part.
            paths.unsampledLightsArriveFirst = scene_->hasEmittingMedia();
            // Lightweight photon mapping's photons carry caustics only: they arrive after
            // one or more delta bounces and end at their first non-delta surface; the
            // camera paths trace a medium's direct light as they trace all the rest.
            if (settings_.lightweight)
                paths.specularOnly = true, paths.firstArrivalDepth = 1, paths.unsampledLightsArriveFirst = false;
            paths.arrivesInMedia = gathersInMedia();
            PhotonPathCounters pathCounters;
            if (teaching) {
                std::vector<uint64_t>& worth = guideWorth_.local();
                worth.resize(guide_->cellCount());
                acc.guideWorth = worth.data();
            }
            GatheringSink sink(*this, acc);
            for (int64_t c = r.begin(); c < r.end() && !cancel.cancelled(); ++c)
                tracePhotonPaths(*scene_, emitter_, paths, c * kPhotonsPerChunk,
                                 std::min(total, (c + 1) * kPhotonsPerChunk), sink, pathCounters);
            sink.flush();
            acc.rays += pathCounters.rays;
            acc.segments += pathCounters.segments;
            return acc;
        },
        [](PhotonCounters a, const PhotonCounters& b) {
            a.rays += b.rays;
            a.segments += b.segments;
            a.candidates += b.candidates;
            a.accepted += b.accepted;
            return a;
        });
    // Summed over the pass's bands (its photons are counted once, in traceOnePass).
    stats_.photonRays += counters.rays;
    stats_.photonSegments += counters.segments;
    stats_.gatherCandidates += counters.candidates;
    stats_.gatherHits += counters.accepted;
}

}  // namespace photon
