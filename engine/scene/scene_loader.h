// Reads the JSON scene format (docs/scene-format.md) into a SceneDescription.
#pragma once
#include <filesystem>
#include <string>
#include <photon/errors.h>
#include <photon/scene_file.h>
#include "description/scene_description.h"

namespace photon {

// Files the scene names (meshes, textures) resolve against `baseDir`; absolute paths and
// paths with ".." are refused.
// `overrides` replace settings of the render and camera blocks before they are read.
SceneDescription loadSceneJson(const std::string& text, const std::filesystem::path& baseDir,
                               const std::vector<SettingOverride>& overrides = {});
SceneDescription loadSceneFile(const std::filesystem::path& file, const std::vector<SettingOverride>& overrides = {});

}  // namespace photon
