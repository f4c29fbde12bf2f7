#include "scene_intake.h"
#include <algorithm>
#include <cstdint>
#include "errors.h"

namespace photon::server {

namespace {

// The overrides are range-checked like the scene fields they replace.
void checkOverride(const char* name, const std::optional<int64_t>& value) {
    if (value && *value < 1)
        throw ServiceError(ErrorKind::BadRequest, std::string(name) + ": must be an integer >= 1");
}

}  // namespace

AcceptedScene validateScene(const std::string& sceneText, const std::filesystem::path& sceneFile,
                            const SubmitOptions& options, const Limits& limits) {
    const SceneFormat format = sceneFormatOf(sceneFile);
    const bool imported = format != SceneFormat::Json;
    // Silently rendering another view than the one asked for would be worse than refusing.
    if (options.camera && !options.camera->empty() && format != SceneFormat::Gltf)
        throw ServiceError(ErrorKind::BadRequest,
                           "camera: chooses among a glTF scene's cameras; this scene has a single camera");
    std::optional<SceneFile> scene;
    try {
        // JSON from its text, as ever; an import reads its file, already stored beside its assets.
        if (imported)
            scene = SceneFile::read(sceneFile, {}, ImportOptions{options.camera.value_or(""), options.lenient.value_or(false)});
        else scene = SceneFile::parseJson(sceneText, sceneFile.parent_path());
    } catch (const SceneError& e) {
        // An imported file's place ("scene.pbrt:12") is no path into photon's JSON scene.
        throw ServiceError(ErrorKind::BadRequest, e.what(), e.path(), !imported);
    }
    checkOverride("passes", options.passes);
    checkOverride("photons_per_pass", options.photonsPerPass);
    RenderSettings& render = scene->render();
    if (options.passes) render.passes = int(std::min<int64_t>(*options.passes, INT32_MAX));
    if (options.photonsPerPass) render.photonsPerPass = *options.photonsPerPass;
    if (options.seed) render.seed = *options.seed;
    if (options.targetError) render.targetError = *options.targetError;

    constexpr ErrorKind kOver = ErrorKind::LimitExceeded;
    checkLimit(kOver,
               "the image's pixel count (" + std::to_string(scene->width()) + " x " + std::to_string(scene->height()) + ")",
               int64_t(scene->width()) * scene->height(), limits, &Limits::maxPixels);
    checkLimit(kOver, "the number of passes", options.passes.value_or(render.passes), limits, &Limits::maxPasses);
    checkLimit(kOver, "the number of photons per pass", render.photonsPerPass, limits, &Limits::maxPhotonsPerPass);
    // Each mesh file is already held to the loader's per-mesh limit; this bounds the sum.
    checkLimit(kOver, "the triangle count of all the scene's meshes", scene->triangleCount(), limits,
               &Limits::maxTriangles);

    JobSettings s;
    s.passes = render.passes;
    s.photonsPerPass = render.photonsPerPass;
    s.seed = render.seed;
    s.integrator = std::string(integratorName(render.integrator));
    s.width = scene->width();
    s.height = scene->height();
    s.camera = options.camera.value_or("");
    s.lenient = imported && options.lenient.value_or(false);
    s.denoise = render.denoise.enabled;
    s.targetError = render.targetError;
    std::vector<std::string> warnings = scene->warnings();
    for (std::string& w : scene->methodWarnings()) warnings.push_back(std::move(w));
    return {s, scene->files(), imported, std::move(warnings)};
}

SceneFile readJobScene(const std::filesystem::path& sceneFile, const JobSettings& settings) {
    SceneFile scene = SceneFile::read(sceneFile, {}, ImportOptions{settings.camera, settings.lenient});
    applySettings(settings, scene.render());
    return scene;
}

void applySettings(const JobSettings& settings, RenderSettings& render) {
    render.passes = settings.passes;
    render.photonsPerPass = settings.photonsPerPass;
    render.seed = settings.seed;
    render.targetError = settings.targetError;
}

}  // namespace photon::server
