// Two-pass photon mapping: construction, the per-pass driver, the camera pass and its
// partition of light paths (docs/photonmap.md), snapshots and checkpoints.
#include "integrators/photon_mapping/photon_mapping.h"
#include "integrators/common/direct_lighting.h"
#include "integrators/common/milliseconds_since.h"

namespace photon {

namespace {

float sceneRadius(const Scene& scene) {
    return std::max(0.5f * length(scene.boundsMax() - scene.boundsMin()), 1e-3f);
}

constexpr unsigned kSmoothLobes = kDiffuseLobe | kGlossyLobe;
// Irradiance is precomputed at every 4th global photon, as Christensen 1999 suggests.
constexpr int kIrradianceStride = 4;

}  // namespace

PhotonMapIntegrator::PhotonMapIntegrator(std::shared_ptr<const Scene> scene)
    : PixelMeanIntegrator(std::move(scene)),
      settings_(scene_->settings()),
      emitter_(*scene_, settings_.projectionMaps),
      // (no maps to build when no caustic photons are asked for)
      causticEmitter_(*scene_, settings_.projectionMaps && settings_.photonMap.causticPhotons > 0,
                      PhotonTargets::SpecularShapes) {
    const PhotonMapSettings& p = settings_.photonMap;
    const float radius = sceneRadius(*scene_);
    globalLookup_ = {p.globalNearest, p.globalMaxRadius > 0 ? p.globalMaxRadius : radius / 10, settings_.kernel};
    causticLookup_ = {p.causticNearest, p.causticMaxRadius > 0 ? p.causticMaxRadius : radius / 40, settings_.kernel};
}

// Photon fluxes are in units of the lights' mean power (PhotonEmitter), so each map's
// photons are worth that power over the number of photons emitted for it.
bool PhotonMapIntegrator::buildMaps(const CancelToken& cancel) {
    const PhotonMapSettings& p = settings_.photonMap;
    const float power = scene_->lights().totalAveragePower();
    PhotonTraceResult g = tracePhotonMap(*scene_, emitter_, PhotonMapKind::Global, p.globalPhotons, cancel);
    if (cancel.cancelled()) return false;
    PhotonTraceResult c = tracePhotonMap(*scene_, causticEmitter_, PhotonMapKind::Caustic, p.causticPhotons, cancel);
    if (cancel.cancelled()) return false;
    global_.build(std::move(g.photons), g.emitted > 0 ? power / static_cast<float>(g.emitted) : 0.0f);
    caustic_.build(std::move(c.photons), c.emitted > 0 ? power / static_cast<float>(c.emitted) : 0.0f);
    if (p.gatherRays > 0 && p.precomputedIrradiance)
        irradiance_ = global_.precomputeIrradiance(g.normals, kIrradianceStride, globalLookup_);
    stats_.globalMapPhotons = int64_t(global_.size());
    stats_.causticMapPhotons = int64_t(caustic_.size());
    // Maps rebuilt after a restored checkpoint are not new work.
    if (passesDone() == 0) {
        stats_.photons = g.emitted + c.emitted;
        stats_.photonMisses = g.misses + c.misses;
        stats_.photonSegments = g.segments + c.segments;
    }
    mapsBuilt_ = true;
    return true;
}

bool PhotonMapIntegrator::preparePass(const CancelToken& cancel) {
    if (mapsBuilt_) return true;
    auto t0 = std::chrono::steady_clock::now();
    if (!buildMaps(cancel)) return false;
    stats_.photonMs = millisecondsSince(t0);
    return true;
}

// The camera path follows delta lobes only (E S*), adding emission it reaches that way;
// at every vertex with non-delta lobes the rest of the light comes from reflectedAt.
Color PhotonMapIntegrator::radiance(const Ray& cameraRay, PathSampler& sampler) const {
    const Scene& scene = *scene_;
    Ray ray = cameraRay;
    Color L(0.0f), beta(1.0f);
    int32_t medium = -1;  // scenes with media are refused (scene-format.md#media)
    for (int depth = 0; depth < settings_.maxDepth; ++depth) {
        SurfaceHit hit;
        if (!traceCameraRay(scene, ray, beta, medium, true, hit, L)) break;
        Vec3 wo = -ray.d;
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        unsigned lobes = sp.material->lobes();
        if (lobes & kSmoothLobes) L += beta * reflectedAt(sp, wo, lobes & kSmoothLobes, sampler);
        if (!(lobes & kDeltaLobe) || depth + 1 == settings_.maxDepth) break;
        const float uLobe = sampler.get1D();
        const Vec2 u = sampler.get2D();
        std::optional<BSDFSample> s = sp.material->sample(sp.frame.toLocal(wo), uLobe, u, sp.inputs,
                                                          TransportMode::Radiance, kDeltaLobe);
        if (!s) break;
        beta *= s->weight;
        if (depth >= 3) {  // Russian roulette on long specular chains
            float q = std::min(1.0f, maxComponent(beta));
            if (sampler.get1D() >= q) break;
            beta /= q;
        }
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
    return L;
}

// Direct light (L D), caustics (L S+ D) and indirect light (L ... D ... D), disjoint.
Color PhotonMapIntegrator::reflectedAt(const ShadingPoint& sp, Vec3 wo, unsigned lobes, PathSampler& sampler) const {
    Color L = sampleDirectLight(*scene_, sp, wo, sampler, lobes);
    L += caustic_.radiance(sp, wo, lobes, causticLookup_);
    if (settings_.photonMap.gatherRays == 0) return L + global_.radiance(sp, wo, lobes, globalLookup_, true);
    // The gather's many rays take the pixel's stream.
    return L + finalGather(sp, wo, lobes, sampler.rng());
}

// Final gathering (Jensen 2001, sec. 9.3.4): rays sampled from the BSDF; where each first
// meets a non-delta surface, the global map's estimate of all light leaving it. Emission
// met on the way is skipped: light sampling and the caustic map already count it.
Color PhotonMapIntegrator::finalGather(const ShadingPoint& sp, Vec3 wo, unsigned lobes, Rng& rng) const {
    const Scene& scene = *scene_;
    const int n = settings_.photonMap.gatherRays;
    const Vec3 woLocal = sp.frame.toLocal(wo);
    Color sum(0.0f);
    for (int i = 0; i < n; ++i) {
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s = sp.material->sample(woLocal, uLobe, u, sp.inputs, TransportMode::Radiance, lobes);
        if (!s) continue;
        Color weight = s->weight;
        Ray ray = spawnRay(sp.hit.p, sp.hit.ng, sp.frame.toWorld(s->wi));
        for (int hop = 0; hop < settings_.maxDepth; ++hop) {
            SurfaceHit hit;
            if (!scene.intersect(ray, hit)) break;
            Vec3 woY = -ray.d;
            ShadingPoint y = makeShadingPoint(scene, hit, woY);
            unsigned lobesY = y.material->lobes();
            if (lobesY & kSmoothLobes) sum += weight * globalRadiance(y, woY, lobesY & kSmoothLobes);
            if (!(lobesY & kDeltaLobe)) break;
            // Through mirrors and glass to the next non-delta surface.
            float uLobeY = rng.uniform();
            Vec2 uY{rng.uniform(), rng.uniform()};
            std::optional<BSDFSample> sy = y.material->sample(y.frame.toLocal(woY), uLobeY, uY, y.inputs,
                                                              TransportMode::Radiance, kDeltaLobe);
            if (!sy) break;
            weight *= sy->weight;
            ray = spawnRay(hit.p, hit.ng, y.frame.toWorld(sy->wi));
        }
    }
    return sum / static_cast<float>(n);
}

// For a Lambertian surface the reflected radiance is f E whatever the photons' directions,
// so the irradiance at the nearest precomputed point facing the same way stands in for a
// k-nearest estimate (Christensen 1999): one small query instead of k BSDF evaluations.
Color PhotonMapIntegrator::globalRadiance(const ShadingPoint& y, Vec3 wo, unsigned lobes) const {
    // Not for a sheet that transmits: the points hold the irradiance of one side only.
    if (irradiance_.size() > 0 && y.material->lobes() == kDiffuseLobe && !y.material->transmits()) {
        if (std::optional<Color> e = irradiance_.lookupIrradiance(y.hit.p, y.hit.ns, globalLookup_.maxRadius)) {
            Color f = y.material->eval(y.frame.toLocal(wo), {0, 0, 1}, y.inputs, TransportMode::Radiance, lobes);
            return f * *e;
        }
    }
    return global_.radiance(y, wo, lobes, globalLookup_);
}

}  // namespace photon
