// Two-pass photon mapping (Jensen 1996; Jensen 2001, "Realistic Image Synthesis Using
// Photon Mapping"). Pass 1, once: photons from the lights build a caustic map (paths
// L S+ D) and a global map (every non-specular hit). Pass 2, every render pass: one
// camera sample per pixel; direct light by light sampling, specular reflection by
// recursion, caustics from the caustic map, indirect light by final gathering into the
// global map (docs/photonmap.md derives why every light path is counted once).
#pragma once
#include <vector>
#include "integrators/common/photon_emitter.h"
#include "math/rng.h"
#include "scene/scene.h"
#include "integrators/photon_mapping/photon_map.h"
#include "integrators/common/pixel_mean.h"

namespace photon {

// Photons traced for one map: which hits are kept, and counts of what happened.
enum class PhotonMapKind { Global, Caustic };
struct PhotonTraceResult {
    std::vector<StoredPhoton> photons;  // chunk by chunk: the same order for any thread count
    std::vector<uint16_t> normals;      // shading normal where each photon was stored, octahedral 16-bit
    int64_t emitted = 0, misses = 0, segments = 0;
};
// Traces `count` photons with random streams keyed by (seed, map kind, photon index), in
// parallel, merged in index order: the same photons for any number of threads.
PhotonTraceResult tracePhotonMap(const Scene& scene, const PhotonEmitter& emitter, PhotonMapKind kind, int64_t count,
                                 const CancelToken& cancel);

// The image is the mean of one camera sample per pixel per pass (PixelMeanIntegrator);
// the maps are built by the first pass and not saved in checkpoints: they depend only on
// the scene and settings, so the first pass after a restore rebuilds the same ones.
class PhotonMapIntegrator final : public PixelMeanIntegrator {
public:
    explicit PhotonMapIntegrator(std::shared_ptr<const Scene> scene);

    const PhotonMap& globalMap() const { return global_; }
    const PhotonMap& causticMap() const { return caustic_; }
    const PhotonMap& irradianceMap() const { return irradiance_; }

private:
    bool preparePass(const CancelToken& cancel) override;
    bool buildMaps(const CancelToken& cancel);
    Color radiance(const Ray& cameraRay, PathSampler& sampler) const override;
    // Light reflected at a camera hit through its non-specular lobes.
    Color reflectedAt(const ShadingPoint& sp, Vec3 wo, unsigned lobes, PathSampler& sampler) const;
    Color finalGather(const ShadingPoint& sp, Vec3 wo, unsigned lobes, Rng& rng) const;
    // Light leaving a gather ray's hit y toward wo: from the precomputed irradiance at y
    // for purely diffuse surfaces where there is one, else the full global-map estimate.
    Color globalRadiance(const ShadingPoint& y, Vec3 wo, unsigned lobes) const;

    const RenderSettings& settings_;
    PhotonEmitter emitter_;         // for the global map: toward every shape
    PhotonEmitter causticEmitter_;  // for the caustic map: toward specular shapes only
    PhotonLookup globalLookup_, causticLookup_;
    PhotonMap global_, caustic_;
    PhotonMap irradiance_;  // precomputed irradiance at every 4th global photon (Christensen 1999)
    bool mapsBuilt_ = false;
};

}  // namespace photon
