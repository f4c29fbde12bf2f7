#include "scene_intake.h"
#include <algorithm>
#include <cstdint>
#include <photon/scene_file.h>
#include "errors.h"

namespace photon::server {

namespace {

// The overrides are range-checked like the scene fields they replace.
void checkOverride(const char* name, const std::optional<int64_t>& value) {
    if (value && *value < 1)
        throw ServiceError(ErrorKind::BadRequest, std::string(name) + ": must be an integer >= 1");
}

}  // namespace

AcceptedScene validateScene(const std::string& sceneText, const std::filesystem::path& folder,
                          const SubmitOptions& options, const Limits& limits) {
    std::optional<SceneFile> scene;
    try {
        scene = SceneFile::parseJson(sceneText, folder);
    } catch (const SceneError& e) {
        throw ServiceError(ErrorKind::BadRequest, e.what(), e.path());
    }
    checkOverride("passes", options.passes);
    checkOverride("photons_per_pass", options.photonsPerPass);
    RenderSettings& render = scene->render();
    if (options.passes) render.passes = int(std::min<int64_t>(*options.passes, INT32_MAX));
    if (options.photonsPerPass) render.photonsPerPass = *options.photonsPerPass;
    if (options.seed) render.seed = *options.seed;

    constexpr ErrorKind kOver = ErrorKind::LimitExceeded;
    checkLimit(kOver, "width*height", int64_t(scene->width()) * scene->height(), limits, &Limits::maxPixels);
    checkLimit(kOver, "passes", options.passes.value_or(render.passes), limits, &Limits::maxPasses);
    checkLimit(kOver, "photons_per_pass", render.photonsPerPass, limits, &Limits::maxPhotonsPerPass);
    // Each mesh file is already held to the loader's per-mesh limit; this bounds the sum.
    checkLimit(kOver, "triangle count", scene->triangleCount(), limits, &Limits::maxTriangles);

    JobSettings s;
    s.passes = render.passes;
    s.photonsPerPass = render.photonsPerPass;
    s.seed = render.seed;
    s.integrator = std::string(integratorName(render.integrator));
    s.width = scene->width();
    s.height = scene->height();
    return {s, scene->files()};
}

void applySettings(const JobSettings& settings, RenderSettings& render) {
    render.passes = settings.passes;
    render.photonsPerPass = settings.photonsPerPass;
    render.seed = settings.seed;
}

}  // namespace photon::server
