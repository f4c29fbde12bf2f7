// Fuzzes the scene format: JSON parsing and every check of loadSceneJson, then Scene::build
// (Embree BVH, lights, camera) for the scenes that load. Files an input names resolve
// against a folder holding the example meshes and textures of scenes/ (plus the names the
// loader tests use), so file references can succeed and reach the mesh and texture code.
//
// Contract checked: loadSceneJson throws only SceneError; Scene::build accepts whatever
// loads (std::runtime_error from Embree is allowed). Anything else escaping, and every
// sanitizer report, is a finding.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include "fuzz_support.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace {

namespace fs = std::filesystem;

// Keeps one input fast: the BVH build is linear in triangles, and the loader already
// bounds everything else by the input's size.
constexpr size_t kMaxBuildTriangles = 20000;

fs::path assetFolder() {
    static const fs::path folder = [] {
        fs::path dir = photon::fuzz::scratchDir("photon-fuzz-scene");
        const fs::path scenes = fs::path(PHOTON_SOURCE_DIR) / "scenes";
        fs::copy(scenes / "meshes", dir / "meshes", fs::copy_options::recursive);
        fs::copy(scenes / "textures", dir / "textures", fs::copy_options::recursive);
        fs::copy_file(scenes / "textures" / "checker.png", dir / "textures" / "wood.png");
        std::ofstream(dir / "meshes" / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                                     "f 1/1 2/2 3/3\n";
        return dir;
    }();
    return folder;
}

size_t triangleCount(const photon::SceneDescription& scene) {
    size_t n = 0;
    for (const photon::ShapeDescription& s : scene.shapes) n += s.mesh.triangleCount();
    return n;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    photon::SceneDescription scene;
    try {
        scene = photon::loadSceneJson(text, assetFolder());
    } catch (const photon::SceneError&) {
        return 0;
    }
    if (triangleCount(scene) > kMaxBuildTriangles) return 0;
    try {
        std::shared_ptr<const photon::Scene> built = photon::Scene::build(std::move(scene));
    } catch (const std::runtime_error&) {
    }
    return 0;
}
