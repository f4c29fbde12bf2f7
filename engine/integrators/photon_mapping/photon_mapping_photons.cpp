// Photon pass of the two-pass photon mapper: photons leave the lights (through the
// projection maps where lights have them), scatter by BSDF sampling with Russian
// roulette, and are stored at non-specular surfaces.
#include <tbb/parallel_for.h>
#include "integrators/common/photon_paths.h"
#include "integrators/photon_mapping/photon_mapping.h"

namespace photon {

namespace {

constexpr int64_t kPhotonsPerChunk = 4096;

struct ChunkResult {
    std::vector<StoredPhoton> photons;
    std::vector<uint16_t> normals;
    int64_t misses = 0, segments = 0;
};

// The global map keeps every photon arriving at a non-specular surface; the caustic map
// only those that came there through one or more specular bounces (L S+ D): the walk hands
// on none straight from the lights and ends paths at their first non-specular bounce.
class StoringSink final : public PhotonArrivalSink {
public:
    explicit StoringSink(ChunkResult& out) : out_(out) {}
    void arrive(const PhotonArrival& a) override {
        out_.photons.emplace_back(a.p, a.wi, a.flux, a.onlySpecular ? 0 : StoredPhoton::kIndirect);
        out_.normals.push_back(StoredPhoton::encodeDirection(a.ns));
    }

private:
    ChunkResult& out_;
};

}  // namespace

PhotonTraceResult tracePhotonMap(const Scene& scene, const PhotonEmitter& emitter, PhotonMapKind kind, int64_t count,
                                 const CancelToken& cancel) {
    const int64_t chunks = (count + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    std::vector<ChunkResult> results(static_cast<size_t>(chunks));
    tbb::parallel_for(int64_t(0), chunks, [&](int64_t c) {
        if (cancel.cancelled()) return;
        const RenderSettings& s = scene.settings();
        const bool caustic = kind == PhotonMapKind::Caustic;
        PhotonPathSettings paths{s.seed, static_cast<uint64_t>(kind), s.maxDepth, caustic, caustic ? 1 : 0};
        StoringSink sink(results[c]);
        PhotonPathCounters counters;
        tracePhotonPaths(scene, emitter, paths, c * kPhotonsPerChunk, std::min(count, (c + 1) * kPhotonsPerChunk),
                         sink, counters);
        results[c].misses = counters.missedAtEmission;
        results[c].segments = counters.segments;
    });
    PhotonTraceResult r;
    r.emitted = count;
    size_t total = 0;
    for (const ChunkResult& c : results) total += c.photons.size();
    r.photons.reserve(total);
    r.normals.reserve(total);
    for (ChunkResult& c : results) {  // chunk order: the same list for any thread count
        r.photons.insert(r.photons.end(), c.photons.begin(), c.photons.end());
        r.normals.insert(r.normals.end(), c.normals.begin(), c.normals.end());
        r.misses += c.misses;
        r.segments += c.segments;
    }
    return r;
}

}  // namespace photon
