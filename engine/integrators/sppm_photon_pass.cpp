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
    std::fill(passFlux_.begin(), passFlux_.end(), 0);
    std::fill(photonCount_.begin(), photonCount_.end(), 0);
    const int64_t total = settings_.photonsPerPass;
    const int64_t chunks = (total + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    stats_.photonSegments = tbb::parallel_reduce(
        tbb::blocked_range<int64_t>(0, chunks, 1), int64_t(0),
        [&](const tbb::blocked_range<int64_t>& r, int64_t segments) {
            for (int64_t c = r.begin(); c < r.end(); ++c) {
                if (cancel.cancelled()) return segments;
                int64_t end = std::min(total, (c + 1) * kPhotonsPerChunk);
                for (int64_t i = c * kPhotonsPerChunk; i < end; ++i) tracePhoton(i, segments);
            }
            return segments;
        },
        std::plus<int64_t>());
    stats_.photons = total;
}

void SppmIntegrator::tracePhoton(int64_t index, int64_t& segments) {
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
        ++segments;
        Vec3 wi = -ray.d;  // toward where the photon came from
        ShadingPoint sp = makeShadingPoint(scene, hit, wi);
        if (!sp.material->isDeltaOnly() && (depth > 0 || depositDirect)) deposit(hit.p, sp.hit.ns, wi, beta);
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

void SppmIntegrator::deposit(Vec3 p, Vec3 n, Vec3 wi, Color flux) {
    const Scene& scene = *scene_;
    const KernelKind kernel = settings_.kernel;
    grid_.forEachCandidate(p, [&](uint32_t i) {
        const VisiblePoint& vp = visible_[i];
        float d2 = lengthSquared(vp.p - p);
        if (d2 > vp.r2) return;
        Vec3 vn = vp.n.decode();
        // Photons on surfaces facing elsewhere (across a corner, the back of a thin wall)
        // do not belong to this point's disc.
        if (dot(vn, n) < 0.5f) return;
        Frame frame = Frame::fromNormal(vn);
        Color f = scene.materialAt(vp.material).eval(vp.woLocal.decode(), frame.toLocal(wi), vp.tint,
                                                     TransportMode::Radiance);
        if (isBlack(f)) return;
        Color c = vp.beta * f * flux * kernelWeight(kernel, d2 / vp.r2);
        for (int k = 0; k < 3; ++k) {
            double v = static_cast<double>(c[k]) * kFluxScale;
            if (!(v >= 1.0)) continue;  // also drops NaN
            auto units = static_cast<uint64_t>(std::min(v, 0x1p62)); 
            std::atomic_ref<uint64_t>(passFlux_[3 * i + k]).fetch_add(units, std::memory_order_relaxed);
        }
        std::atomic_ref<uint32_t>(photonCount_[i]).fetch_add(1, std::memory_order_relaxed);
    });
}

}  // namespace photon
