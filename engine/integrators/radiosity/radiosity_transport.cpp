#include "integrators/radiosity/radiosity_transport.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <atomic>
#include <numeric>
#include "math/frame.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace photon {

namespace {

// Random streams of the setup, one per patch and task.
enum SetupStream : uint64_t { kFormFactorStream = 0, kDirectStream = 1 };

// Jittered samples in [0,1)^2 over a k x k grid (k = floor(sqrt(count))) in a random order,
// then plain random ones for the rest: the two 2D parts of a ray (where on the patch,
// which direction) are each stratified, and paired at random.
class Stratified2D {
public:
    Stratified2D(int count, Rng& rng) : k_(static_cast<int>(std::sqrt(static_cast<double>(count)))), order_(k_ * k_) {
        std::iota(order_.begin(), order_.end(), 0);
        for (size_t i = order_.size(); i > 1; --i) std::swap(order_[i - 1], order_[rng.next() % i]);
    }
    Vec2 operator()(int i, Rng& rng) const {
        if (i >= static_cast<int>(order_.size())) return {rng.uniform(), rng.uniform()};
        int s = order_[i];
        return {(static_cast<float>(s % k_) + rng.uniform()) / k_, (static_cast<float>(s / k_) + rng.uniform()) / k_};
    }

private:
    int k_;
    std::vector<int> order_;
};

// Runs body(patchIndex) over all patches in parallel; false if cancelled.
template <class Body>
bool forEachPatch(size_t count, const CancelToken& cancel, Body body) {
    std::atomic<bool> stopped{false};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 16), [&](const tbb::blocked_range<size_t>& range) {
        if (cancel.cancelled()) {
            stopped = true;
            return;
        }
        for (size_t i = range.begin(); i < range.end(); ++i) body(i);
    });
    return !stopped && !cancel.cancelled();
}

}  // namespace

std::optional<FormFactors> computeFormFactors(const Scene& scene, const PatchMesh& mesh, const RadiosityLights& lights,
                                              uint64_t seed, const CancelToken& cancel) {
    const std::vector<Patch>& patches = mesh.patches();
    const int raysPerPatch = lights.raysPerPatch();
    FormFactors result;
    result.rows.resize(patches.size());
    result.emitterIrradiance.assign(patches.size(), Color(0.0f));
    std::vector<int64_t> escaped(patches.size(), 0);
    bool done = forEachPatch(patches.size(), cancel, [&](size_t i) {
        const Patch& patch = patches[i];
        if (!(patch.area > 0)) return;
        Rng rng(seed, kFormFactorStream, i, StreamPurpose::Setup);
        Stratified2D points(raysPerPatch, rng), directions(raysPerPatch, rng);
        std::vector<uint32_t> landed;
        landed.reserve(raysPerPatch);
        Color emitted(0.0f);
        for (int r = 0; r < raysPerPatch; ++r) {
            PatchMesh::SurfaceSample s = mesh.sample(patch, points(r, rng));
            Vec3 local = sampleCosineHemisphere(directions(r, rng));
            Vec3 d = Frame::fromNormal(s.n).toWorld(local);
            SurfaceHit hit;
            if (!scene.intersect(spawnRay(s.p, s.n, d), hit)) {
                ++escaped[i];
                continue;
            }
            std::optional<CellPoint> at = mesh.locate(hit);
            if (!at) continue;
            uint32_t j = mesh.patchSeenFrom(*at, hit, -d);
            landed.push_back(j);
            const Color& E = patches[j].exitance;
            if (!isBlack(E)) emitted += E * (kInvPi * local.z * lights.misScale(j, local.z, hit.t, dot(hit.ng, -d)));
        }
        result.emitterIrradiance[i] = emitted;
        std::sort(landed.begin(), landed.end());
        std::vector<FormFactorEntry>& row = result.rows[i];
        for (size_t k = 0; k < landed.size();) {
            size_t end = k;
            while (end < landed.size() && landed[end] == landed[k]) ++end;
            row.push_back({landed[k], static_cast<float>(end - k) / static_cast<float>(raysPerPatch)});
            k = end;
        }
    });
    if (!done) return std::nullopt;
    for (size_t i = 0; i < patches.size(); ++i)
        if (patches[i].area > 0) result.rays += raysPerPatch;
    result.escaped = std::accumulate(escaped.begin(), escaped.end(), int64_t(0));
    return result;
}

namespace {

// Light-sampled half of the emitters' MIS estimate: Le cos / (K p_light + N p_cosine) per sample.
Color emitterSamples(const Scene& scene, const PatchMesh& mesh, const RadiosityLights& lights, const Patch& patch,
                     Rng& rng) {
    const int samples = lights.directSamples();
    Stratified2D points(samples, rng), lightPoints(samples, rng);
    Color sum(0.0f);
    for (int k = 0; k < samples; ++k) {
        PatchMesh::SurfaceSample s = mesh.sample(patch, points(k, rng));
        std::optional<RadiosityLights::EmitterPick> pick = lights.pickEmitter(rng.uniform());
        Vec2 u = lightPoints(k, rng);
        if (!pick) continue;
        const Patch& emitter = mesh.patches()[pick->patch];
        PatchMesh::SurfaceSample e = mesh.sample(emitter, u);
        Vec3 toLight = e.p - s.p;
        float distance = length(toLight);
        if (!(distance > 0)) continue;
        Vec3 wi = toLight / distance;
        float cosReceiver = dot(s.n, wi), cosEmitter = -dot(e.n, wi);
        if (cosReceiver <= 0 || cosEmitter <= 0) continue;
        if (scene.occluded(spawnRayTo(s.p, s.n, e.p))) continue;
        sum += emitter.exitance * (kInvPi * cosReceiver * lights.misScale(pick->patch, cosReceiver, distance, cosEmitter));
    }
    return sum;
}

// Each light that is not a shape: E = int L cos dw, estimated by (L / pdf) cos; delta
// lights give the irradiance at normal incidence directly.
Color otherLightSamples(const Scene& scene, const PatchMesh& mesh, const RadiosityLights& lights, const Patch& patch,
                        Rng& rng) {
    const int samples = lights.directSamples();
    Color sum(0.0f);
    for (const auto& light : lights.others()) {
        Stratified2D points(samples, rng), lightPoints(samples, rng);
        for (int k = 0; k < samples; ++k) {
            PatchMesh::SurfaceSample s = mesh.sample(patch, points(k, rng));
            std::optional<LightSample> ls = light->sampleIncident(s.p, s.n, lightPoints(k, rng));
            if (!ls) continue;
            float cosine = dot(s.n, ls->wi);
            if (cosine <= 0) continue;
            Ray shadow = std::isinf(ls->distance) ? spawnRay(s.p, s.n, ls->wi)
                                                  : spawnRayTo(s.p, s.n, s.p + ls->wi * ls->distance);
            if (!scene.occluded(shadow)) sum += ls->weight * (cosine / static_cast<float>(samples));
        }
    }
    return sum;
}

}  // namespace

std::optional<std::vector<Color>> directIrradiance(const Scene& scene, const PatchMesh& mesh,
                                                   const RadiosityLights& lights, uint64_t seed,
                                                   const CancelToken& cancel) {
    const std::vector<Patch>& patches = mesh.patches();
    std::vector<Color> irradiance(patches.size(), Color(0.0f));
    bool done = forEachPatch(patches.size(), cancel, [&](size_t i) {
        const Patch& patch = patches[i];
        if (!(patch.area > 0)) return;
        Rng rng(seed, kDirectStream, i, StreamPurpose::Setup);
        irradiance[i] = emitterSamples(scene, mesh, lights, patch, rng) + otherLightSamples(scene, mesh, lights, patch, rng);
    });
    if (!done) return std::nullopt;
    return irradiance;
}

}  // namespace photon
