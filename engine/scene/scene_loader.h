// Reads the JSON scene format (docs/scene-format.md) into a SceneDescription.
#pragma once
#include <filesystem>
#include <string>
#include <photon/errors.h>
#include <photon/scene_file.h>
#include "description/scene_description.h"
#include "description/imported_scene.h"

namespace photon {

// Files the scene names (meshes, textures) resolve against `baseDir`; absolute paths and
// paths with ".." are refused.
// `overrides` replace settings of the render and camera blocks before they are read.
SceneDescription loadSceneJson(const std::string& text, const std::filesystem::path& baseDir,
                               const std::vector<SettingOverride>& overrides = {});
SceneDescription loadSceneFile(const std::filesystem::path& file, const std::vector<SettingOverride>& overrides = {});
// A scene an importer made (description/imported_scene.h): its document read as JSON, its
// in-memory meshes and files found by the names the document gives them.
SceneDescription loadImportedScene(const ImportedScene& imported, const std::filesystem::path& baseDir,
                                   const std::vector<SettingOverride>& overrides = {});

}  // namespace photon
