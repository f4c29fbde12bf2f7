#include "photon_paths.h"
#include "photon_roulette.h"

namespace photon {

namespace {

void tracePhotonPath(const Scene& scene, const PhotonEmitter& emitter, const PhotonPathSettings& settings,
                     const RngStream& stream, int64_t index, PhotonArrivalSink& sink, PhotonPathCounters& counters) {
    Rng rng(stream, static_cast<uint64_t>(index));
    std::optional<EmittedPhoton> emitted = emitter.emit(rng);
    if (!emitted) return;
    Color beta = emitted->beta;
    Ray ray = emitted->ray;
    bool onlySpecular = true;
    for (int depth = 0; depth < settings.maxDepth; ++depth) {
        SurfaceHit hit;
        ++counters.rays;
        if (!scene.intersect(ray, hit)) {
            counters.missedAtEmission += depth == 0;
            return;
        }
        ++counters.segments;
        Vec3 wi = -ray.d;
        ShadingPoint sp = makeShadingPoint(scene, hit, wi);
        if (!sp.material->isDeltaOnly()) sink.arrive({sp, wi, beta, depth, onlySpecular});
        if (depth + 1 == settings.maxDepth) return;
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s =
            sp.material->sample(sp.frame.toLocal(wi), uLobe, u, sp.tint, TransportMode::Importance);
        if (!s) return;
        onlySpecular = onlySpecular && s->delta;
        if (settings.specularOnly && !onlySpecular) return;
        std::optional<Color> next = photonAfterRoulette(beta, s->weight, rng);
        if (!next) return;
        beta = *next;
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
}

}  // namespace

void tracePhotonPaths(const Scene& scene, const PhotonEmitter& emitter, const PhotonPathSettings& settings,
                      int64_t begin, int64_t end, PhotonArrivalSink& sink, PhotonPathCounters& counters) {
    const RngStream stream(settings.seed, settings.stream, StreamPurpose::Photon);
    for (int64_t i = begin; i < end; ++i) tracePhotonPath(scene, emitter, settings, stream, i, sink, counters);
}

}  // namespace photon
