// Shared by the scene-loader tests: a scene folder in /tmp with textures and meshes (some
// of them broken or out of reach), the full example scene, and error-checking helpers.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <nlohmann/json.hpp>
#include "math/transform.h"
#include "scene/json_reader.h"
#include "scene/mesh_loader.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "texture/image_texture.h"

namespace photon::test {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// ---- fixture files: a scene folder in /tmp with textures and meshes ----

inline void writeText(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

// Writes w x h pixels of `channels` channels to p, in the format its extension names, as
// 8-bit, 16-bit or float samples by T (uint8_t, uint16_t, float); colour is written as given
// even where alpha is 0. Fails the test if it cannot. (scene_loader_fixture.cpp: the
// programs that include this header need not parse OpenImageIO's, 3.7 s each.)
template <typename T>
void writeImage(const fs::path& p, int w, int h, int channels, const std::vector<T>& pixels);

// A triangle with normals and uvs, for the file-mesh path.
inline const char* const kTriangleObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 0 1\n"
    "vn 0 0 1\n"
    "f 1/1/1 2/2/1 3/3/1\n";

// One triangle in a glTF with an embedded buffer, placed by a node translation (0, 0, 5).
inline std::string gltfTriangle(const std::string& bufferUri) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0, "translation": [0, 0, 5]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"byteLength": 44, "uri": ")" + bufferUri + R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}
inline const char* const kTriangleBufferBase64 = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=";

// The same 44 bytes as a file: 3 float positions, then 3 uint16 indices and padding.
inline std::string triangleBuffer() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    std::string bytes(reinterpret_cast<const char*>(positions), sizeof positions);
    bytes.append(reinterpret_cast<const char*>(indices), sizeof indices);
    return bytes;
}

struct Fixture {
    fs::path root;   // holds the scene folder and files that must stay out of reach
    fs::path scene;  // the scene folder: baseDir for loadSceneJson

    Fixture() {
        root = fs::temp_directory_path() / ("photon-scene-test-" + std::to_string(::getpid()));
        scene = root / "scene";
        fs::remove_all(root);
        fs::create_directories(scene);
        // 2x2 sRGB texture: top row red, green; bottom row blue, white.
        writeImage<uint8_t>(scene / "textures/wood.png", 2, 2, 3,
                            {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
        writeText(scene / "textures/corrupt.png", "this is not a PNG");
        writeText(scene / "meshes/tri.obj", kTriangleObj);
        writeText(scene / "meshes/corrupt.obj", "f 7 8 9\nthis is not an OBJ file\n");
        writeText(scene / "meshes/tri.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n2 0 0\n0 2 0\n3 0 1 2\n");
        writeText(scene / "meshes/tri.gltf",
                  gltfTriangle(std::string("data:application/octet-stream;base64,") + kTriangleBufferBase64));
        writeText(scene / "meshes/escape.gltf", gltfTriangle("../../outside.bin"));
        writeText(scene / "meshes/external.gltf", gltfTriangle("external.bin"));
        writeText(scene / "meshes/external.bin", triangleBuffer());
        writeText(root / "outside.obj", kTriangleObj);
        writeText(root / "outside.bin", triangleBuffer());
        fs::create_symlink(root / "outside.obj", scene / "meshes/link.obj");
    }
    ~Fixture() {
        std::error_code ec;
        fs::remove_all(root, ec);
    }
};

inline const Fixture& fixture() {
    static Fixture f;
    return f;
}

// The scene format's full example, with every field set to something other than its default.
inline const char* const kFullScene = R"({
  "camera": {"type": "perspective", "position": [0, 1, 6.8], "look_at": [0, 1, 0], "up": [0, 1, 0],
             "fov": 19.5, "resolution": [640, 480], "aperture_radius": 0.05, "focus_distance": 6.5},
  "materials": {
    "white":  {"type": "diffuse", "albedo": [0.725, 0.71, 0.68]},
    "wood":   {"type": "diffuse", "albedo": {"texture": "textures/wood.png"}},
    "glass":  {"type": "dielectric", "ior": 1.5},
    "mirror": {"type": "mirror", "reflectance": [0.95, 0.95, 0.95]},
    "metal":  {"type": "conductor", "reflectance": [0.9, 0.6, 0.3], "roughness": 0.2},
    "gloss":  {"type": "plastic", "albedo": [0.1, 0.2, 0.6], "ior": 1.5, "roughness": 0.05}
  },
  "shapes": [
    {"type": "quad", "origin": [-1, 0, -1], "edge_u": [0, 0, 2], "edge_v": [2, 0, 0], "material": "wood"},
    {"type": "quad", "origin": [-1, 0, -1], "edge_u": [2, 0, 0], "edge_v": [0, 2, 0], "material": "white",
     "flip_normals": true},
    {"type": "mesh", "file": "meshes/tri.obj", "material": "metal",
     "transform": {"scale": 0.5, "rotate": {"axis": [0, 1, 0], "angle": 90}, "translate": [1, 2, 3]}},
    {"type": "sphere", "center": [0.4, 0.3, 0.2], "radius": 0.3, "material": "glass"},
    {"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2],
     "normals": [[1, 1, 0], [0, 0, 1], [0, 0, 2]], "uvs": [[0, 0], [1, 0], [0, 1]], "material": "gloss",
     "transform": {"scale": [2, 3, 4], "translate": [1, 1, 1]}},
    {"type": "quad", "origin": [-0.25, 1.98, -0.25], "edge_u": [0.5, 0, 0], "edge_v": [0, 0, 0.5],
     "material": "mirror", "emission": [17, 12, 4]}
  ],
  "lights": [
    {"type": "point", "position": [0, 1.5, 0], "intensity": [5, 5, 5]},
    {"type": "spot", "position": [0, 1.9, 0], "direction": [0, -2, 0], "intensity": [10, 10, 10], "cone_angle": 30},
    {"type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3]},
    {"type": "environment", "radiance": [0.1, 0.1, 0.1]}
  ],
  "render": {"integrator": "path", "passes": 16, "photons_per_pass": 1000, "time_limit": 2.5,
             "initial_radius": "auto", "alpha": 0.7, "max_depth": 5, "seed": 42, "kernel": "biweight",
             "exposure": -1, "direct": "photons"}
})";

inline Json fullScene() { return Json::parse(kFullScene); }

inline SceneDescription load(const Json& doc) { return photon::loadSceneJson(doc.dump(), fixture().scene); }

// The SceneError `text` raises; a test failure if it loads or throws anything else.
inline SceneError errorFromText(const std::string& text) {
    try {
        photon::loadSceneJson(text, fixture().scene);
    } catch (const SceneError& e) {
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a SceneError: " << e.what();
        return SceneError("?", "?");
    }
    ADD_FAILURE() << "loaded without error";
    return SceneError("?", "?");
}

// Loads the full scene after `edit`, expecting exactly `path: message`.
inline void expectError(const std::function<void(Json&)>& edit, const std::string& path, const std::string& message) {
    Json doc = fullScene();
    edit(doc);
    SceneError e = errorFromText(doc.dump());
    EXPECT_EQ(e.path(), path);
    EXPECT_EQ(std::string(e.what()), path.empty() ? message : path + ": " + message);
}

// The material `fields` loaded as "tested" in the full scene (kept alive for the caller).
inline const Material& loadedMaterial(const Json& fields) {
    static std::vector<SceneDescription> kept;
    Json doc = fullScene();
    doc["materials"]["tested"] = fields;
    kept.push_back(load(doc));
    const SceneDescription& d = kept.back();
    for (size_t i = 0; i < d.materialNames.size(); ++i)
        if (d.materialNames[i] == "tested") return *d.materials[i];
    ADD_FAILURE() << "no material \"tested\"";
    return *d.materials[0];
}

// The reflectance at normal incidence of a material whose reflection there is a mirror (with
// the material's own inputs, as integrators pass them).
inline Color mirrorReflectance(const Material& m) {
    auto s = m.sample(Vec3(0, 0, 1), 0.5f, {0.5f, 0.5f}, m.inputsAt({}), TransportMode::Radiance);
    EXPECT_TRUE(s && s->delta);
    return s ? s->weight : Color(0.0f);
}

}  // namespace photon::test
