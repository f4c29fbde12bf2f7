#include "projection_misses.h"
#include <chrono>
#include "integrators/common/photon_emitter.h"
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace photon::bench {

namespace {

struct Misses {
    double fraction = 0, emitMs = 0;
};

Misses measure(const SceneDescription& description, bool projectionMaps, int photons) {
    auto scene = Scene::build(description);
    auto t0 = std::chrono::steady_clock::now();
    PhotonEmitter emitter(*scene, projectionMaps);
    Misses m;
    m.emitMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    int64_t misses = 0;
    for (int i = 0; i < photons; ++i) {
        Rng rng(1, 0, static_cast<uint64_t>(i), StreamPurpose::Photon);
        std::optional<EmittedPhoton> e = emitter.emit(rng);
        SurfaceHit hit;
        misses += !e || !scene->intersect(e->ray, hit);
    }
    m.fraction = static_cast<double>(misses) / photons;
    return m;
}

}  // namespace

nlohmann::json projectionMapMisses(const std::string& sceneFile, int photons) {
    SceneDescription d = loadSceneFile(sceneFile);
    Misses without = measure(d, false, photons), with = measure(d, true, photons);
    return {{"scene", sceneFile},
            {"photons", photons},
            {"miss_fraction_without", without.fraction},
            {"miss_fraction_with", with.fraction},
            {"miss_reduction", with.fraction > 0 ? without.fraction / with.fraction : 0.0},
            {"projection_map_build_ms", with.emitMs}};
}

}  // namespace photon::bench
