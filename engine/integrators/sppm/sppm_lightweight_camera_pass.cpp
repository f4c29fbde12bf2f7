// Lightweight photon mapping's camera path (render.lightweight; after Grittmann, Georgiev,
// Slusallek and Krivanek 2018, "Efficient Caustic Rendering with Lightweight Photon
// Mapping"): a whole path-traced sample per pixel, which also leaves a visible point on its
// first vertex with a diffuse lobe. Photons then bring only caustics there: light that
// reached the point straight from delta bounces (L S+ D), which path tracing finds only by
// chance. Every light path is counted once: the path tracer leaves out, at that vertex,
// the diffuse lobe's share of light it finds through one or more delta bounces, and
// counts everything else (docs/sppm.md, "Lightweight photon mapping").
#include "integrators/common/direct_lighting.h"
#include "integrators/sppm/sppm.h"

namespace photon {

namespace {

// The vertex the visible point is on, kept for weighing the light its path tracer's own
// continuation finds through delta bounces.
struct GatherVertex {
    ShadingPoint sp;
    Vec3 woLocal;
    unsigned lobes = 0;  // the lobes photons are gathered through there
    Vec3 wiLocal;        // the direction its BSDF sample left by (non-delta samples only)
};

// Share of f(wo, wi) at the gather vertex that photons do not bring: the lobes beside the
// gathered ones, channel by channel (0 when all lobes are gathered).
Color pathTracedShare(const GatherVertex& v) {
    if (v.lobes == kAllLobes) return Color(0.0f);
    const Material& m = *v.sp.material;
    const Color f = m.eval(v.woLocal, v.wiLocal, v.sp.inputs, TransportMode::Radiance);
    const Color gathered = m.eval(v.woLocal, v.wiLocal, v.sp.inputs, TransportMode::Radiance, v.lobes);
    Color share(0.0f);
    for (int c = 0; c < 3; ++c) share[c] = f[c] > 0 ? std::clamp(1.0f - gathered[c] / f[c], 0.0f, 1.0f) : 0.0f;
    return share;
}

}  // namespace

int SppmIntegrator::tracePixelLightweight(size_t index, Rng& rng) {
    const Scene& scene = *scene_;
    PathSampler sampler = pathSampler(index, rng, 0);
    const Camera::PixelSample start = startPixel(index, sampler);
    Color L(0.0f), beta(start.weight);
    Ray ray = start.ray;
    BounceSampling bounce;
    const BsdfContinuation next{kAllLobes, 1.0f};
    std::optional<GatherVertex> gather;
    // Delta bounces since the gather vertex's non-delta sample; -1 once the path has left
    // that chain (or before it starts). Light found with at least one is a caustic.
    int deltaChain = -1;
    float pathLength = 0;
    const int maxDepth = settings_.maxDepth;
    int rays = 0;  // a light sample's shadow ray counted as one whether or not it is cast
    int32_t medium = scene.description().camera.medium;
    for (int depth = 0;; ++depth) {
        SurfaceHit hit;
        Color found(0.0f);
        ++rays;
        const bool hitSurface = traceCameraRay(scene, ray, beta, medium, bounce, hit, found);
        L += deltaChain > 0 ? found * pathTracedShare(*gather) : found;
        if (!hitSurface || depth == maxDepth) break;
        pathLength += hit.t;
        Vec3 wo = -ray.d;
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        const Material& m = *sp.material;
        const Vec3 woLocal = sp.frame.toLocal(wo);
        if (!m.isDeltaOnly()) L += beta * sampleDirectLight(scene, sp, wo, sampler, kAllLobes, next, medium), ++rays;
        const bool gathersHere = !gather && m.hasDiffuse();
        if (gathersHere) {
            // Photons are gathered through the diffuse lobe alone where there are others
            // beside it: through a sharp highlight they would show as fireflies.
            const unsigned lobes = (m.lobes() & ~kDiffuseLobe) ? kDiffuseLobe : kAllLobes;
            storeVisiblePoint(index, sp, wo, beta, lobes, pathLength);
            gather = GatherVertex{sp, woLocal, lobes, {}};
        }
        const float uLobe = sampler.get1D();
        const Vec2 u = sampler.get2D();
        std::optional<BSDFSample> s = m.sample(woLocal, uLobe, u, sp.inputs, TransportMode::Radiance);
        if (!s) break;
        if (gathersHere) {
            // A delta sample here leaves the gathered lobe: whatever the path finds is its own.
            if (!s->delta) gather->wiLocal = s->wi, deltaChain = 0;
        } else if (deltaChain >= 0) {
            deltaChain = s->delta ? deltaChain + 1 : -1;
        }
        beta *= s->weight;
        bounce = bounceFrom(sp, *s);
        if (depth >= 3 && !survivesRoulette(beta, sampler.get1D())) break;  // as the path tracer
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
        medium = scene.mediumToward(hit, ray.d, medium);
    }
    result(index).direct = SharedExponentColor::of(L, rng.uniform());  // the pixel's last draw
    result(index).choice = {};
    result(index).extraPaths = 0;
    return rays;
}

}  // namespace photon
