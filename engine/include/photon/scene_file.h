// A scene as read from its file, before it is built for rendering: what a caller checks
// (image size, triangles, render settings) and may override before a Renderer takes it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <photon/errors.h>
#include <photon/render_settings.h>

namespace photon {

struct SceneDescription;

class SceneFile {
public:
    // The JSON scene format (docs/scene-format.md). Files the scene names (meshes,
    // textures) resolve against `baseDir`; absolute paths and paths with ".." are refused.
    // Throws SceneError naming the JSON path of what is wrong.
    static SceneFile parseJson(const std::string& text, const std::filesystem::path& baseDir);
    static SceneFile read(const std::filesystem::path& file);

    explicit SceneFile(SceneDescription description);
    SceneFile(SceneFile&&) noexcept;
    SceneFile& operator=(SceneFile&&) noexcept;
    ~SceneFile();

    // The scene's "render" block: the settings a Renderer made from it uses.
    RenderSettings& render();
    const RenderSettings& render() const;
    int width() const;
    int height() const;
    // Triangles of all meshes together (spheres are not meshed).
    int64_t triangleCount() const;

    // The description itself, for the engine.
    SceneDescription& description() { return *description_; }

private:
    std::unique_ptr<SceneDescription> description_;
};

}  // namespace photon
