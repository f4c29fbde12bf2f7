// SPPM photon pass: photons leave the lights in proportion to power, bounce by BSDF
// sampling with Russian roulette, and at every non-delta hit add their flux to the
// visible points whose gather disc holds the hit.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <atomic>
#include "shading.h"
#include "sppm.h"

namespace photon {

namespace {
constexpr int64_t kPhotonsPerChunk = 4096;

// Normalised kernels k(d^2/r^2) whose integral over the unit disc, divided by pi, is 1,
// so the estimate keeps the form tau / (pi r^2 N). Biweight: (3/pi)(1 - x^2)^2 scaled by pi.
inline float kernelWeight(KernelKind kind, float d2OverR2) {
    if (kind == KernelKind::Uniform) return 1.0f;
    float t = 1.0f - d2OverR2;
    return 3.0f * t * t;
}
}  // namespace

void SppmIntegrator::photonPass(const CancelToken& cancel) {
    const int64_t total = settings_.photonsPerPass;
    const int64_t chunks = (total + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    PhotonCounters counters = tbb::parallel_reduce(
        tbb::blocked_range<int64_t>(0, chunks, 1), PhotonCounters{},
        [&](const tbb::blocked_range<int64_t>& r, PhotonCounters acc) {
            for (int64_t c = r.begin(); c < r.end(); ++c) {
                if (cancel.cancelled()) return acc;
                int64_t end = std::min(total, (c + 1) * kPhotonsPerChunk);
                for (int64_t i = c * kPhotonsPerChunk; i < end; ++i) tracePhoton(i, acc);
            }
            return acc;
        },
        [](PhotonCounters a, const PhotonCounters& b) {
            a.segments += b.segments;
            a.candidates += b.candidates;
            a.accepted += b.accepted;
            return a;
        });
    stats_.photons = total;
    stats_.photonSegments = counters.segments;
    stats_.gatherCandidates = counters.candidates;
    stats_.gatherHits = counters.accepted;
}

void SppmIntegrator::tracePhoton(int64_t index, PhotonCounters& counters) {
    const Scene& scene = *scene_;
    Rng rng(settings_.seed, static_cast<uint64_t>(passes_), static_cast<uint64_t>(index), StreamPurpose::Photon);
    LightSampler::Pick pick = scene.lights().pick(rng.uniform());
    Vec2 uPos{rng.uniform(), rng.uniform()}, uDir{rng.uniform(), rng.uniform()};
    if (!pick.light) return;
    std::optional<PhotonEmission> e = pick.light->emitPhoton(uPos, uDir);
    if (!e) return;
    // Flux in units of the lights' mean power, so a photon's flux averages 1.
    Color beta = e->flux / (pick.probability * scene.lights().totalAveragePower());
    Ray ray = isBlack(e->normal) ? Ray{e->origin, e->direction} : spawnRay(e->origin, e->normal, e->direction);
    const bool depositDirect = settings_.direct == DirectLighting::Photons;
    for (int depth = 0; depth < settings_.maxDepth; ++depth) {
        SurfaceHit hit;
        if (!scene.intersect(ray, hit)) break;
        ++counters.segments;
        Vec3 wi = -ray.d;  // toward where the photon came from
        ShadingPoint sp = makeShadingPoint(scene, hit, wi);
        if (!sp.material->isDeltaOnly() && (depth > 0 || depositDirect)) deposit(hit.p, sp.hit.ns, wi, beta, counters);
        if (depth + 1 == settings_.maxDepth) break;
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s = sp.material->sample(sp.frame.toLocal(wi), uLobe, u, sp.tint,
                                                          TransportMode::Importance);
        if (!s) break;
        // Russian roulette on the throughput's largest channel keeps surviving photons'
        // flux about constant (pbrt-v4 SPPM; Jensen 2001, 5.2.1).
        Color next = beta * s->weight;
        float q = maxComponent(next) / maxComponent(beta);
        if (q < 1) {
            if (rng.uniform() >= q) break;
            next /= q;
        }
        if (!(maxComponent(next) > 0) || !isFinite(next)) break;
        beta = next;
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
}

void SppmIntegrator::deposit(Vec3 p, Vec3 n, Vec3 wi, Color flux, PhotonCounters& counters) {
    const Scene& scene = *scene_;
    const KernelKind kernel = settings_.kernel;
    grid_.forEachCandidate(p, [&](uint32_t i) {
        const GatherDisc& disc = discs_[i];
        ++counters.candidates;
        float d2 = lengthSquared(disc.p - p);
        if (d2 > disc.r2) return;
        VisiblePoint& vp = visible_[i];
        Vec3 vn = vp.n.decode();
        // Photons on surfaces facing elsewhere (across a corner, the back of a thin wall)
        // do not belong to this point's disc.
        if (dot(vn, n) < 0.5f) return;
        Frame frame = Frame::fromNormal(vn);
        Color f = scene.materialAt(vp.material).eval(vp.woLocal.decode(), frame.toLocal(wi), vp.tint,
                                                     TransportMode::Radiance);
        if (isBlack(f)) return;
        ++counters.accepted;
        Color c = vp.beta * f * flux * kernelWeight(kernel, d2 / disc.r2);
        for (int k = 0; k < 3; ++k) {
            double v = static_cast<double>(c[k]) * kFluxScale;
            if (!(v >= 1.0)) continue;  // also drops NaN
            auto units = static_cast<uint64_t>(std::min(v, 0x1p62)); 
            std::atomic_ref<uint64_t>(vp.flux[k]).fetch_add(units, std::memory_order_relaxed);
        }
        std::atomic_ref<uint32_t>(vp.photonCount).fetch_add(1, std::memory_order_relaxed);
    }, [&](uint32_t i) { __builtin_prefetch(&discs_[i]); });
}

}  // namespace photon
