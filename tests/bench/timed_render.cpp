#include "timed_render.h"
#include <chrono>
#include <cmath>
#include <photon/render.h>
#include <photon/scene_file.h>
#include "scene/scene.h"

namespace photon::bench {

SceneDescription describeScene(const std::string& sceneFile, const std::vector<SettingOverride>& overrides) {
    SceneFile file = SceneFile::read(sceneFile, overrides);
    return std::move(file.description());
}

TimedRender renderFor(SceneDescription d, double seconds) {
    d.render.passes = 1'000'000;
    d.render.timeLimitSeconds = seconds;
    d.render.denoise.enabled = false;
    const auto start = std::chrono::steady_clock::now();
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {renderer.rawSnapshot(), renderer.progress().pass, elapsed};
}

double meanOf(const Image& image) {
    double sum = 0;
    for (float v : image.rgb) sum += v;
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

double relativeNoise(const Image& a, const Image& b) {
    return rmse(a, b) / std::sqrt(2.0) / (0.5 * (meanOf(a) + meanOf(b)));
}

}  // namespace photon::bench
