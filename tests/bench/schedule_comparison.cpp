#include "schedule_comparison.h"
#include <chrono>
#include <cmath>
#include <photon/render.h>
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace photon::bench {
namespace {

struct TimedRender {
    Image image;
    int passes = 0;
};

TimedRender renderFor(const std::string& sceneFile, RadiusSchedule schedule, uint64_t seed, double seconds) {
    SceneDescription d = loadSceneFile(sceneFile);
    d.render.radiusSchedule = schedule;
    d.render.seed = seed;
    d.render.passes = 1'000'000;
    d.render.timeLimitSeconds = seconds;
    d.render.denoise.enabled = false;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    return {renderer.rawSnapshot(), renderer.progress().pass};
}

double meanOf(const Image& image) {
    double sum = 0;
    for (float v : image.rgb) sum += v;
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

}  // namespace

nlohmann::json compareRadiusSchedules(const std::string& sceneFile, double seconds, double referenceSeconds) {
    const TimedRender reference = renderFor(sceneFile, RadiusSchedule::PerPixel, 1000, referenceSeconds);
    const double referenceMean = meanOf(reference.image);
    nlohmann::json out = {{"scene", sceneFile},
                          {"seconds_each", seconds},
                          {"reference", {{"schedule", "pixel"}, {"passes", reference.passes}}}};
    for (auto [name, schedule] : {std::pair{"pixel", RadiusSchedule::PerPixel}, std::pair{"global", RadiusSchedule::Global}}) {
        const TimedRender a = renderFor(sceneFile, schedule, 1, seconds), b = renderFor(sceneFile, schedule, 2, seconds);
        const double mean = 0.5 * (meanOf(a.image) + meanOf(b.image));
        out["schedules"][name] = {{"passes", (a.passes + b.passes) / 2},
                                  {"relative_noise", rmse(a.image, b.image) / std::sqrt(2.0) / mean},
                                  {"bias_of_mean", mean / referenceMean - 1},
                                  {"relative_rmse", 0.5 * (rmse(a.image, reference.image) + rmse(b.image, reference.image)) / referenceMean}};
    }
    return out;
}

}  // namespace photon::bench
