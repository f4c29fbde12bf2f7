#include "radiosity_transport.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <atomic>
#include <numeric>
#include "../math/frame.h"
#include "../math/rng.h"
#include "../math/sampling.h"

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

std::optional<FormFactors> computeFormFactors(const Scene& scene, const PatchMesh& mesh, int raysPerPatch,
                                              uint64_t seed, const CancelToken& cancel) {
    const std::vector<Patch>& patches = mesh.patches();
    FormFactors result;
    result.rows.resize(patches.size());
    std::vector<int64_t> escaped(patches.size(), 0);
    bool done = forEachPatch(patches.size(), cancel, [&](size_t i) {
        const Patch& patch = patches[i];
        if (!(patch.area > 0)) return;
        Rng rng(seed, kFormFactorStream, i, StreamPurpose::Setup);
        Stratified2D points(raysPerPatch, rng), directions(raysPerPatch, rng);
        std::vector<uint32_t> landed;
        landed.reserve(raysPerPatch);
        for (int r = 0; r < raysPerPatch; ++r) {
            PatchMesh::SurfaceSample s = mesh.sample(patch, points(r, rng));
            Vec3 d = Frame::fromNormal(s.n).toWorld(sampleCosineHemisphere(directions(r, rng)));
            SurfaceHit hit;
            if (!scene.intersect(spawnRay(s.p, s.n, d), hit)) {
                ++escaped[i];
                continue;
            }
            if (auto at = mesh.locate(hit)) landed.push_back(mesh.patchSeenFrom(*at, hit, -d));
        }
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

std::optional<std::vector<Color>> directIrradiance(const Scene& scene, const PatchMesh& mesh, int samples,
                                                   uint64_t seed, const CancelToken& cancel) {
    const std::vector<Patch>& patches = mesh.patches();
    std::vector<Color> irradiance(patches.size(), Color(0.0f));
    if (scene.lights().size() == 0) return irradiance;
    bool done = forEachPatch(patches.size(), cancel, [&](size_t i) {
        const Patch& patch = patches[i];
        if (!(patch.area > 0)) return;
        Rng rng(seed, kDirectStream, i, StreamPurpose::Setup);
        Stratified2D points(samples, rng), lightPoints(samples, rng);
        Color sum(0.0f);
        for (int k = 0; k < samples; ++k) {
            PatchMesh::SurfaceSample s = mesh.sample(patch, points(k, rng));
            LightSampler::Pick pick = scene.lights().pick(rng.uniform());
            if (!pick.light) continue;
            std::optional<LightSample> ls = pick.light->sampleIncident(s.p, s.n, lightPoints(k, rng));
            if (!ls) continue;
            float cosine = dot(s.n, ls->wi);
            if (cosine <= 0) continue;
            Ray shadow = std::isinf(ls->distance) ? spawnRay(s.p, s.n, ls->wi)
                                                  : spawnRayTo(s.p, s.n, s.p + ls->wi * ls->distance);
            if (scene.occluded(shadow)) continue;
            // E = int L cos dw, estimated by (L / pdf) cos; delta lights give irradiance directly.
            sum += ls->weight * (cosine / pick.probability);
        }
        irradiance[i] = sum / static_cast<float>(samples);
    });
    if (!done) return std::nullopt;
    return irradiance;
}

}  // namespace photon
