// Photon pass of the two-pass photon mapper: photons leave the lights (through the
// projection maps where lights have them), scatter by BSDF sampling with Russian
// roulette, and are stored at non-specular surfaces.
#include <tbb/parallel_for.h>
#include "photon_roulette.h"
#include "photonmap.h"
#include "shading.h"

namespace photon {

namespace {

constexpr int64_t kPhotonsPerChunk = 4096;

struct ChunkResult {
    std::vector<StoredPhoton> photons;
    std::vector<uint16_t> normals;
    int64_t misses = 0, segments = 0;
};

// The global map keeps every photon arriving at a non-specular surface; the caustic map
// only those that came there through one or more specular bounces (L S+ D), so a caustic
// photon's path ends at its first non-specular bounce.
void tracePhoton(const Scene& scene, const PhotonEmitter& emitter, PhotonMapKind kind, int64_t index,
                 ChunkResult& out) {
    const RenderSettings& s = scene.settings();
    Rng rng(s.seed, static_cast<uint64_t>(kind), static_cast<uint64_t>(index), StreamPurpose::Photon);
    std::optional<EmittedPhoton> emitted = emitter.emit(rng);
    if (!emitted) return;
    Color beta = emitted->beta;
    Ray ray = emitted->ray;
    bool onlySpecular = true;  // every bounce so far was off a delta lobe
    for (int depth = 0; depth < s.maxDepth; ++depth) {
        SurfaceHit hit;
        if (!scene.intersect(ray, hit)) {
            out.misses += depth == 0;
            break;
        }
        ++out.segments;
        Vec3 wi = -ray.d;  // toward where the photon came from
        ShadingPoint sp = makeShadingPoint(scene, hit, wi);
        const bool store = kind == PhotonMapKind::Global || (depth > 0 && onlySpecular);
        if (!sp.material->isDeltaOnly() && store) {
            out.photons.emplace_back(hit.p, wi, beta, onlySpecular ? 0 : StoredPhoton::kIndirect);
            out.normals.push_back(StoredPhoton::encodeDirection(sp.hit.ns));
        }
        if (depth + 1 == s.maxDepth) break;
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> b = sp.material->sample(sp.frame.toLocal(wi), uLobe, u, sp.tint,
                                                          TransportMode::Importance);
        if (!b) break;
        onlySpecular = onlySpecular && b->delta;
        if (kind == PhotonMapKind::Caustic && !onlySpecular) break;
        // The material picks the lobe (diffuse, specular reflection or transmission); then
        // Russian roulette on the lobe's reflectance decides absorption.
        std::optional<Color> next = photonAfterRoulette(beta, b->weight, rng);
        if (!next) break;
        beta = *next;
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(b->wi));
    }
}

}  // namespace

PhotonTraceResult tracePhotonMap(const Scene& scene, const PhotonEmitter& emitter, PhotonMapKind kind, int64_t count,
                                 const CancelToken& cancel) {
    const int64_t chunks = (count + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    std::vector<ChunkResult> results(static_cast<size_t>(chunks));
    tbb::parallel_for(int64_t(0), chunks, [&](int64_t c) {
        if (cancel.cancelled()) return;
        int64_t end = std::min(count, (c + 1) * kPhotonsPerChunk);
        for (int64_t i = c * kPhotonsPerChunk; i < end; ++i) tracePhoton(scene, emitter, kind, i, results[c]);
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
