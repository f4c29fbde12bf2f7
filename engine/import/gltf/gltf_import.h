// glTF 2.0 scenes (.gltf, .glb) as photon JSON scenes: docs/import-gltf.md says what maps
// to what, what is approximated and what is refused.
#pragma once
#include <filesystem>
#include <string>
#include "description/imported_scene.h"

namespace photon {

struct GltfImportOptions {
    // The name of the camera to look through; empty: the first camera in node order.
    std::string camera;
};

// Reads the file and returns the equivalent photon scene, its meshes (one per primitive,
// "meshes/<mesh>-<primitive>.ply") and embedded images ("textures/<image>.<png|jpg>") held
// in memory; render it with loadImportedScene(result, file's folder). Throws SceneError
// whose path() names the file and, where there is one, a JSON pointer into it
// ("scene.gltf: /materials/2/extensions/KHR_materials_volume: ...").
ImportedScene importGltf(const std::filesystem::path& file, const GltfImportOptions& options = {});

}  // namespace photon
