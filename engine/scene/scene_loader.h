// Reads the JSON scene format (docs/scene-format.md) into a SceneDescription.
#pragma once
#include <filesystem>
#include <string>
#include <photon/errors.h>
#include "description/scene_description.h"

namespace photon {

// Files the scene names (meshes, textures) resolve against `baseDir`; absolute paths and
// paths with ".." are refused.
SceneDescription loadSceneJson(const std::string& text, const std::filesystem::path& baseDir);
SceneDescription loadSceneFile(const std::filesystem::path& file);

}  // namespace photon
