#include "integrator_comparison.h"
#include <chrono>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace photon::bench {

namespace {

struct TimedRender {
    Image image;
    int passes = 0;
    double seconds = 0;
};

TimedRender renderFor(const std::string& sceneFile, IntegratorKind kind, double seconds) {
    SceneDescription d = loadSceneFile(sceneFile);
    d.render.integrator = kind;
    d.render.passes = 1'000'000;
    d.render.timeLimitSeconds = seconds;
    d.render.denoise.enabled = false;  // the integrators themselves are compared
    auto start = std::chrono::steady_clock::now();
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {renderer.snapshot(), renderer.progress().pass, elapsed};
}

double meanOf(const Image& image) {
    double sum = 0;
    for (float v : image.rgb) sum += v;
    return image.rgb.empty() ? 0.0 : sum / static_cast<double>(image.rgb.size());
}

}  // namespace

nlohmann::json compareIntegrators(const std::string& sceneFile, double seconds, double referenceSeconds) {
    TimedRender reference = renderFor(sceneFile, IntegratorKind::Sppm, referenceSeconds);
    const double referenceMean = meanOf(reference.image);
    nlohmann::json out = {{"scene", sceneFile},
                          {"seconds_each", seconds},
                          {"reference", {{"integrator", "sppm"}, {"passes", reference.passes}, {"seconds", reference.seconds}}}};
    for (std::string_view name : kIntegratorNames) {
        TimedRender r = renderFor(sceneFile, *integratorNamed(name), seconds);
        double error = rmse(r.image, reference.image);
        out["integrators"][std::string(name)] = {
            {"passes", r.passes},
            {"seconds", r.seconds},
            {"rmse", error},
            {"relative_rmse", referenceMean > 0 ? error / referenceMean : 0.0},  // over the reference's mean
            {"mean_over_reference_mean", referenceMean > 0 ? meanOf(r.image) / referenceMean : 0.0}};
    }
    return out;
}

}  // namespace photon::bench
