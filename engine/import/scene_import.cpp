#include "import/scene_import.h"
#include <photon/errors.h>
#include "import/gltf/gltf_import.h"
#include "import/pbrt/pbrt_import.h"
#include "scene/scene_paths.h"

namespace photon {

SceneFormat sceneFormatOf(const std::filesystem::path& file) {
    const std::string e = lowerCaseExtension(file);
    if (e == ".pbrt") return SceneFormat::Pbrt;
    if (e == ".gltf" || e == ".glb") return SceneFormat::Gltf;
    return SceneFormat::Json;
}

ImportedScene importSceneFile(const std::filesystem::path& file, const ImportOptions& options) {
    switch (sceneFormatOf(file)) {
        case SceneFormat::Pbrt: return importPbrt(file, options.lenient);
        case SceneFormat::Gltf: return importGltf(file, GltfImportOptions{options.camera});
        case SceneFormat::Json: break;
    }
    throw SceneError("", file.filename().string() + " is not a scene format photon imports (.pbrt, .gltf, .glb)");
}

}  // namespace photon
