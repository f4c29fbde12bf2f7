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

class SceneFile {
public:
    // The JSON scene format (docs/scene-format.md). Files the scene names (meshes,
    // textures) resolve against `baseDir`; absolute paths and paths with ".." are refused.
    // Throws SceneError naming the JSON path of what is wrong.
    static SceneFile parseJson(const std::string& text, const std::filesystem::path& baseDir,
                               const std::vector<SettingOverride>& overrides = {});
    static SceneFile read(const std::filesystem::path& file, const std::vector<SettingOverride>& overrides = {});

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
    // times instances place it (spheres are not meshed).
    int64_t triangleCount() const;
    // The files the scene named (meshes, textures), relative to its folder in normal form
    // ("meshes/a.obj"), sorted.
    const std::vector<std::string>& files() const;

    // The description itself, for the engine.
    SceneDescription& description() { return *description_; }

private:
    std::unique_ptr<SceneDescription> description_;
};

}  // namespace photon
