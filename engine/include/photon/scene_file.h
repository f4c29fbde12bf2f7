// A scene as read from its file, before it is built for rendering: what a caller checks
// (image size, triangles, render settings) and may override before a Renderer takes it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#include <photon/errors.h>
#include <photon/render_settings.h>

namespace photon {

struct SceneDescription;

// A setting given apart from the scene, e.g. on a command line: `key` is its path in the
// scene ("render.passes", "camera.resolution", "render.photonmap.gather_rays"), `value` its
// JSON ("16", "[640, 480]", "true") or, when that is not JSON, a string. Only the render
// and camera blocks can be overridden; the value is checked as the scene's own would be.
struct SettingOverride {
    std::string key, value;
};

// The formats a scene file may be in, by its extension: photon's JSON (.json and anything
// else), pbrt-v4 (.pbrt) or glTF 2.0 (.gltf, .glb), the last two imported (docs/import.md).
enum class SceneFormat { Json, Pbrt, Gltf };
SceneFormat sceneFormatOf(const std::filesystem::path& file);

// Choices an import needs beyond the file.
struct ImportOptions {
    std::string camera;  // glTF: the camera's name (empty: the first)
    // pbrt: what photon cannot render (media that scatter, unknown materials, textures,
    // shapes and lights) is left out or replaced, each with a
    // warning, instead of failing the import (docs/import.md, "Lenient import").
    bool lenient = false;
};

class SceneFile {
public:
    // The JSON scene format (docs/scene-format.md). Files the scene names (meshes,
    // textures) resolve against `baseDir`; absolute paths and paths with ".." are refused.
    // Throws SceneError naming the JSON path of what is wrong.
    static SceneFile parseJson(const std::string& text, const std::filesystem::path& baseDir,
                               const std::vector<SettingOverride>& overrides = {});
    // A scene file in any format photon reads (sceneFormatOf); imported ones keep the
    // importer's warnings. The overrides apply on top of the file's own settings.
    static SceneFile read(const std::filesystem::path& file, const std::vector<SettingOverride>& overrides = {},
                          const ImportOptions& options = {});

    explicit SceneFile(SceneDescription description);
    SceneFile(SceneFile&&) noexcept;
    SceneFile& operator=(SceneFile&&) noexcept;
    ~SceneFile();

    // The scene's "render" block: the settings a Renderer made from it uses.
    RenderSettings& render();
    const RenderSettings& render() const;
    int width() const;
    int height() const;
    // Triangles of all meshes together, as held in memory: an object's once, however many
    // times instances place it (spheres are not meshed). Each curve segment counts as one:
    // Embree's hierarchy holds about as much for it as for a triangle.
    int64_t triangleCount() const;
    // The files the scene named (meshes, textures), relative to its folder in normal form
    // ("meshes/a.obj"), sorted.
    const std::vector<std::string>& files() const;

    // What an import approximated or left out, each naming where ("scene.pbrt:12: ...");
    // empty for photon's JSON.
    const std::vector<std::string>& warnings() const { return warnings_; }
    // What the render method (render.integrator) leaves out of this scene, in plain words:
    // radiosity, diffuse interreflection only, names the materials without a diffuse part
    // (their caustics and reflections are missing). Empty when the method renders it all.
    std::vector<std::string> methodWarnings() const;

    // The description itself, for the engine.
    SceneDescription& description() { return *description_; }

private:
    std::unique_ptr<SceneDescription> description_;
    std::vector<std::string> warnings_;
};

}  // namespace photon
