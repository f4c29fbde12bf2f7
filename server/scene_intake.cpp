#include "scene_intake.h"
#include <algorithm>
#include <cstdint>
#include "errors.h"
#include "scene/scene_loader.h"

namespace photon::server {

namespace {

int64_t triangleCount(const SceneDescription& description) {
    int64_t total = 0;
    for (const ShapeDescription& shape : description.shapes)
        if (shape.kind == ShapeDescription::Kind::Mesh) total += int64_t(shape.mesh.triangleCount());
    return total;
}

// The overrides are range-checked like the scene fields they replace.
void checkOverride(const char* name, const std::optional<int64_t>& value) {
    if (value && *value < 1)
        throw ServiceError(ErrorKind::BadRequest, std::string(name) + ": must be an integer >= 1");
}

}  // namespace

JobSettings validateScene(const std::string& sceneText, const std::filesystem::path& folder,
                          const SubmitOptions& options, const Limits& limits) {
    SceneDescription description;
    try {
        description = loadSceneJson(sceneText, folder);
    } catch (const SceneError& e) {
        throw ServiceError(ErrorKind::BadRequest, e.what(), e.path());
    }
    checkOverride("passes", options.passes);
    checkOverride("photons_per_pass", options.photonsPerPass);
    RenderSettings& render = description.render;
    if (options.passes) render.passes = int(std::min<int64_t>(*options.passes, INT32_MAX));
    if (options.photonsPerPass) render.photonsPerPass = *options.photonsPerPass;
    if (options.seed) render.seed = *options.seed;

    const CameraDescription& camera = description.camera;
    constexpr ErrorKind kOver = ErrorKind::LimitExceeded;
    checkLimit(kOver, "width*height", int64_t(camera.width) * camera.height, limits.maxPixels, "--max-pixels");
    checkLimit(kOver, "passes", options.passes.value_or(render.passes), limits.maxPasses, "--max-passes");
    checkLimit(kOver, "photons_per_pass", render.photonsPerPass, limits.maxPhotonsPerPass, "--max-photons");
    // Each mesh file is already held to the loader's per-mesh limit; this bounds the sum.
    checkLimit(kOver, "triangle count", triangleCount(description), limits.maxTriangles, "--max-triangles");

    JobSettings s;
    s.passes = render.passes;
    s.photonsPerPass = render.photonsPerPass;
    s.seed = render.seed;
    s.integrator = std::string(integratorName(render.integrator));
    s.width = camera.width;
    s.height = camera.height;
    return s;
}

void applySettings(const JobSettings& settings, SceneDescription& description) {
    description.render.passes = settings.passes;
    description.render.photonsPerPass = settings.photonsPerPass;
    description.render.seed = settings.seed;
}

}  // namespace photon::server
