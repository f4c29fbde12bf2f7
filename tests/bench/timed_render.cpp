#include "timed_render.h"
#include <chrono>
#include <cmath>
#include <photon/render.h>
#include <photon/scene_file.h>
#include "film/pixel_errors.h"
#include "scene/scene.h"

namespace photon::bench {

SceneDescription describeScene(const std::string& sceneFile, const std::vector<SettingOverride>& overrides) {
    SceneFile file = SceneFile::read(sceneFile, overrides);
    return std::move(file.description());
}

namespace {
TimedRender render(SceneDescription d) {
    d.render.denoise.enabled = false;
    const auto start = std::chrono::steady_clock::now();
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {renderer.rawSnapshot(), renderer.progress().pass, elapsed, renderer.progress().relativeError};
}
}  // namespace

TimedRender renderFor(SceneDescription d, double seconds) {
    d.render.passes = 1'000'000;
    d.render.timeLimitSeconds = seconds;
    return render(std::move(d));
}

TimedRender renderPasses(SceneDescription d, int passes) {
    d.render.passes = passes;
    d.render.timeLimitSeconds = 0;
    d.render.targetError = 0;
    return render(std::move(d));
}

RenderPair renderPairFor(SceneDescription d, double seconds) {
    SceneDescription second = d;
    d.render.seed = 1, second.render.seed = 2;
    RenderPair pair;
    pair.a = renderFor(std::move(d), seconds);
    pair.b = renderPasses(std::move(second), pair.a.passes);
    return pair;
}

double meanOf(const Image& image) {
    double sum = 0;
    for (float v : image.rgb) sum += v;
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

double relativeNoise(const Image& a, const Image& b) {
    return rmse(a, b) / std::sqrt(2.0) / (0.5 * (meanOf(a) + meanOf(b)));
}

double relativeNoiseOfLuminance(const Image& a, const Image& b) {
    const size_t n = size_t(a.width) * a.height;
    std::vector<float> ya(n), yb(n), mean(n);
    for (size_t i = 0; i < n; ++i) {
        ya[i] = luminance(Color(a.rgb[3 * i], a.rgb[3 * i + 1], a.rgb[3 * i + 2]));
        yb[i] = luminance(Color(b.rgb[3 * i], b.rgb[3 * i + 1], b.rgb[3 * i + 2]));
        mean[i] = 0.5f * (ya[i] + yb[i]);
    }
    const std::vector<bool> keep = errorPixels(mean, a.width, a.height);
    double sum = 0, d2 = 0;
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i)
        if (keep[i]) sum += mean[i], d2 += double(ya[i] - yb[i]) * (ya[i] - yb[i]), ++kept;
    return kept && sum > 0 ? std::sqrt(d2 / double(kept)) / std::sqrt(2.0) / (sum / double(kept)) : 0.0;
}

}  // namespace photon::bench
