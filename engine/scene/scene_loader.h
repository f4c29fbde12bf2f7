// Reads the JSON scene format (docs/scene-format.md) into a SceneDescription.
#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>
#include "scene_description.h"

namespace photon {

// Every problem with a scene: `path` is the JSON path of the offending value
// (e.g. "shapes[3].radius"), empty for problems with the document as a whole.
class SceneError : public std::runtime_error {
public:
    SceneError(std::string path, const std::string& message)
        : std::runtime_error(path.empty() ? message : path + ": " + message), path_(std::move(path)) {}
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Files the scene names (meshes, textures) resolve against `baseDir`; absolute paths and
// paths with ".." are refused.
SceneDescription loadSceneJson(const std::string& text, const std::filesystem::path& baseDir);
SceneDescription loadSceneFile(const std::filesystem::path& file);

}  // namespace photon
