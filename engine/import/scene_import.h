// The formats photon imports besides its own JSON, chosen by a file's extension.
#pragma once
#include <filesystem>
#include <photon/scene_file.h>
#include "description/imported_scene.h"

namespace photon {

// Reads a .pbrt (pbrt-v4), .gltf or .glb (glTF 2.0) file as a photon scene. Throws
// SceneError naming the file and where in it (line, JSON pointer) what is wrong is.
ImportedScene importSceneFile(const std::filesystem::path& file, const ImportOptions& options);

}  // namespace photon
