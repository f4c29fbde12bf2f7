// SPPM photon pass: photons leave the lights in proportion to power, bounce by BSDF
// sampling with Russian roulette, and at every non-delta hit add their flux to the
// visible points whose gather disc holds the hit.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <atomic>
#include "photon_roulette.h"
#include "shading.h"
#include "sppm_gather_batch.h"

namespace photon {

namespace {
constexpr int64_t kPhotonsPerChunk = 4096;

}  // namespace

void SppmIntegrator::photonPass(const CancelToken& cancel) {
    const int64_t total = settings_.photonsPerPass;
    const int64_t chunks = (total + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    PhotonCounters counters = tbb::parallel_reduce(
        tbb::blocked_range<int64_t>(0, chunks, 1), PhotonCounters{},
        [&](const tbb::blocked_range<int64_t>& r, PhotonCounters acc) {
            GatherBatch batch;
            for (int64_t c = r.begin(); c < r.end(); ++c) {
                if (cancel.cancelled()) return acc;
                int64_t end = std::min(total, (c + 1) * kPhotonsPerChunk);
                for (int64_t i = c * kPhotonsPerChunk; i < end; ++i) tracePhoton(i, batch, acc);
            }
            gather(batch, acc);
            return acc;
        },
        [](PhotonCounters a, const PhotonCounters& b) {
            a.rays += b.rays;
            a.segments += b.segments;
            a.candidates += b.candidates;
            a.accepted += b.accepted;
            return a;
        });
    stats_.photons = total;
    stats_.photonRays = counters.rays;
    stats_.photonSegments = counters.segments;
    stats_.gatherCandidates = counters.candidates;
    stats_.gatherHits = counters.accepted;
}

void SppmIntegrator::tracePhoton(int64_t index, GatherBatch& batch, PhotonCounters& counters) {
    const Scene& scene = *scene_;
    Rng rng(settings_.seed, static_cast<uint64_t>(passes_), static_cast<uint64_t>(index), StreamPurpose::Photon);
    std::optional<EmittedPhoton> emitted = emitter_.emit(rng);
    if (!emitted) return;
    Color beta = emitted->beta;
    Ray ray = emitted->ray;
    const bool depositDirect = settings_.direct == DirectLighting::Photons;
    for (int depth = 0; depth < settings_.maxDepth; ++depth) {
        SurfaceHit hit;
        ++counters.rays;
        if (!scene.intersect(ray, hit)) break;
        ++counters.segments;
        Vec3 wi = -ray.d;  // toward where the photon came from
        ShadingPoint sp = makeShadingPoint(scene, hit, wi);
        if (!sp.material->isDeltaOnly() && (depth > 0 || depositDirect)) {
            batch.push({sp.hit.p, sp.hit.ns, wi, beta});
            if (batch.full()) gather(batch, counters);
        }
        if (depth + 1 == settings_.maxDepth) break;
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s = sp.material->sample(sp.frame.toLocal(wi), uLobe, u, sp.tint,
                                                          TransportMode::Importance);
        if (!s) break;
        std::optional<Color> next = photonAfterRoulette(beta, s->weight, rng);
        if (!next) break;
        beta = *next;
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
}

}  // namespace photon
