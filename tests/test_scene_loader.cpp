// The JSON scene loader (engine/scene/json_*.cpp), the mesh loader and texture loading:
// a full scene parses to the expected values; every kind of bad input gives an exact
// SceneError naming the JSON path; the example scenes in scenes/ load.
#include <gtest/gtest.h>
#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>
#include "math/transform.h"
#include "scene/json_reader.h"
#include "scene/mesh_loader.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "texture/texture.h"

namespace fs = std::filesystem;
using photon::Color;
using photon::SceneDescription;
using photon::SceneError;
using photon::Vec2;
using photon::Vec3;
using Json = nlohmann::ordered_json;

namespace {

#define EXPECT_VEC3_NEAR(a, b, tol)       \
    do {                                  \
        Vec3 a_ = (a), b_ = (b);          \
        EXPECT_NEAR(a_.x, b_.x, tol);     \
        EXPECT_NEAR(a_.y, b_.y, tol);     \
        EXPECT_NEAR(a_.z, b_.z, tol);     \
    } while (0)

// ---- fixture files: a scene folder in /tmp with textures and meshes ----

void writeText(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

template <typename T>
void writeImage(const fs::path& p, int w, int h, int channels, OIIO::TypeDesc type, const std::vector<T>& pixels) {
    fs::create_directories(p.parent_path());
    auto out = OIIO::ImageOutput::create(p.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(w, h, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // write colour as given, even where alpha is 0
    ASSERT_TRUE(out->open(p.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
    out->close();
}

// A triangle with normals and uvs, for the file-mesh path.
const char* kTriangleObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 0 1\n"
    "vn 0 0 1\n"
    "f 1/1/1 2/2/1 3/3/1\n";

// One triangle in a glTF with an embedded buffer, placed by a node translation (0, 0, 5).
std::string gltfTriangle(const std::string& bufferUri) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0, "translation": [0, 0, 5]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"byteLength": 44, "uri": ")" + bufferUri + R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}
const char* kTriangleBufferBase64 = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=";

// The same 44 bytes as a file: 3 float positions, then 3 uint16 indices and padding.
std::string triangleBuffer() {
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
        writeImage<uint8_t>(scene / "textures/wood.png", 2, 2, 3, OIIO::TypeDesc::UINT8,
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

const Fixture& fixture() {
    static Fixture f;
    return f;
}

// The brief's example scene, with every field set to something other than its default.
const char* kFullScene = R"({
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

Json fullScene() { return Json::parse(kFullScene); }

SceneDescription load(const Json& doc) { return photon::loadSceneJson(doc.dump(), fixture().scene); }

// The SceneError `text` raises; a test failure if it loads or throws anything else.
SceneError errorFromText(const std::string& text) {
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
void expectError(const std::function<void(Json&)>& edit, const std::string& path, const std::string& message) {
    Json doc = fullScene();
    edit(doc);
    SceneError e = errorFromText(doc.dump());
    EXPECT_EQ(e.path(), path);
    EXPECT_EQ(std::string(e.what()), path.empty() ? message : path + ": " + message);
}

}  // namespace

// ---- a valid scene ----

TEST(SceneLoader, FullSceneCamera) {
    SceneDescription s = load(fullScene());
    EXPECT_VEC3_NEAR(s.camera.position, Vec3(0, 1, 6.8f), 0);
    EXPECT_VEC3_NEAR(s.camera.lookAt, Vec3(0, 1, 0), 0);
    EXPECT_VEC3_NEAR(s.camera.up, Vec3(0, 1, 0), 0);
    EXPECT_FLOAT_EQ(s.camera.fovDegrees, 19.5f);
    EXPECT_EQ(s.camera.width, 640);
    EXPECT_EQ(s.camera.height, 480);
    EXPECT_FLOAT_EQ(s.camera.apertureRadius, 0.05f);
    EXPECT_FLOAT_EQ(s.camera.focusDistance, 6.5f);
}

TEST(SceneLoader, FullSceneMaterials) {
    SceneDescription s = load(fullScene());
    ASSERT_EQ(s.materials.size(), 6u);
    EXPECT_EQ(s.materialNames, (std::vector<std::string>{"white", "wood", "glass", "mirror", "metal", "gloss"}));
    for (const auto& m : s.materials) EXPECT_TRUE(m);
    EXPECT_VEC3_NEAR(s.materials[0]->tint().value, Vec3(0.725f, 0.71f, 0.68f), 0);
    ASSERT_TRUE(s.materials[1]->tint().textured());
    EXPECT_EQ(s.materials[1]->tint().texture->width(), 2);
    EXPECT_VEC3_NEAR(s.materials[3]->tint().value, Color(0.95f), 0);
    EXPECT_VEC3_NEAR(s.materials[4]->tint().value, Vec3(0.9f, 0.6f, 0.3f), 0);
}

TEST(SceneLoader, FullSceneQuads) {
    SceneDescription s = load(fullScene());
    ASSERT_EQ(s.shapes.size(), 6u);
    const auto& floor = s.shapes[0];
    EXPECT_EQ(floor.kind, photon::ShapeDescription::Kind::Mesh);
    EXPECT_EQ(floor.name, "shapes[0]");
    EXPECT_EQ(floor.material, 1u);
    ASSERT_EQ(floor.mesh.triangleCount(), 2u);
    ASSERT_EQ(floor.mesh.normals.size(), 4u);
    ASSERT_EQ(floor.mesh.uvs.size(), 4u);
    EXPECT_VEC3_NEAR(floor.mesh.positions[2], Vec3(1, 0, 1), 0);  // origin + u + v
    EXPECT_EQ(floor.mesh.uvs[2].x, 1);
    EXPECT_EQ(floor.mesh.uvs[2].y, 1);
    // u x v = (0,0,2) x (2,0,0) = +y, and both triangles are wound to agree with it.
    for (size_t t = 0; t < 2; ++t) {
        const auto& m = floor.mesh;
        Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
             p2 = m.positions[m.indices[3 * t + 2]];
        EXPECT_VEC3_NEAR(photon::normalize(photon::cross(p1 - p0, p2 - p0)), Vec3(0, 1, 0), 1e-6);
    }
    for (Vec3 n : floor.mesh.normals) EXPECT_VEC3_NEAR(n, Vec3(0, 1, 0), 1e-6);
    EXPECT_FALSE(floor.flipNormals);
    EXPECT_TRUE(s.shapes[1].flipNormals);
    EXPECT_VEC3_NEAR(s.shapes[5].emission, Vec3(17, 12, 4), 0);
    EXPECT_VEC3_NEAR(s.shapes[0].emission, Vec3(0, 0, 0), 0);
}

TEST(SceneLoader, FullSceneFileMeshIsTransformed) {
    SceneDescription s = load(fullScene());
    const auto& m = s.shapes[2].mesh;
    EXPECT_EQ(s.shapes[2].material, 4u);
    ASSERT_EQ(m.triangleCount(), 1u);
    ASSERT_EQ(m.normals.size(), 3u);
    ASSERT_EQ(m.uvs.size(), 3u);
    // scale 0.5, rotate 90 degrees about +y (x -> -z), translate (1, 2, 3).
    EXPECT_VEC3_NEAR(m.positions[m.indices[0]], Vec3(1, 2, 3), 1e-6);
    EXPECT_VEC3_NEAR(m.positions[m.indices[1]], Vec3(1, 2, 2.5f), 1e-6);
    EXPECT_VEC3_NEAR(m.positions[m.indices[2]], Vec3(1, 2.5f, 3), 1e-6);
    EXPECT_VEC3_NEAR(m.normals[m.indices[0]], Vec3(1, 0, 0), 1e-6);
    EXPECT_NEAR(m.uvs[m.indices[1]].x, 1, 0);
    EXPECT_NEAR(m.uvs[m.indices[2]].y, 1, 0);
}

TEST(SceneLoader, FullSceneSphereAndInlineMesh) {
    SceneDescription s = load(fullScene());
    const auto& sphere = s.shapes[3];
    EXPECT_EQ(sphere.kind, photon::ShapeDescription::Kind::Sphere);
    EXPECT_VEC3_NEAR(sphere.center, Vec3(0.4f, 0.3f, 0.2f), 0);
    EXPECT_FLOAT_EQ(sphere.radius, 0.3f);
    EXPECT_EQ(sphere.material, 2u);

    const auto& m = s.shapes[4].mesh;  // scale (2, 3, 4), then translate (1, 1, 1)
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_VEC3_NEAR(m.positions[0], Vec3(1, 1, 1), 0);
    EXPECT_VEC3_NEAR(m.positions[1], Vec3(3, 1, 1), 0);
    EXPECT_VEC3_NEAR(m.positions[2], Vec3(1, 4, 1), 0);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
    // Normals take the inverse transpose: (1, 1, 0) -> (1/2, 1/3, 0), normalised.
    EXPECT_VEC3_NEAR(m.normals[0], photon::normalize(Vec3(0.5f, 1 / 3.0f, 0)), 1e-6);
    EXPECT_VEC3_NEAR(m.normals[2], Vec3(0, 0, 1), 1e-6);  // [0, 0, 2] arrives normalised
    EXPECT_EQ(m.uvs[2].y, 1);
}

TEST(SceneLoader, FullSceneLights) {
    SceneDescription s = load(fullScene());
    using Kind = photon::LightDescription::Kind;
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(s.lights[0].kind, Kind::Point);
    EXPECT_VEC3_NEAR(s.lights[0].position, Vec3(0, 1.5f, 0), 0);
    EXPECT_VEC3_NEAR(s.lights[0].intensity, Color(5), 0);
    EXPECT_EQ(s.lights[1].kind, Kind::Spot);
    EXPECT_VEC3_NEAR(s.lights[1].direction, Vec3(0, -1, 0), 0);  // normalised
    EXPECT_FLOAT_EQ(s.lights[1].coneAngleDegrees, 30);
    EXPECT_FLOAT_EQ(s.lights[1].falloffAngleDegrees, 25);  // default: 5/6 of the cone
    EXPECT_EQ(s.lights[2].kind, Kind::Directional);
    EXPECT_VEC3_NEAR(s.lights[2].irradiance, Color(3), 0);
    EXPECT_EQ(s.lights[3].kind, Kind::Environment);
    EXPECT_VEC3_NEAR(s.lights[3].radiance, Color(0.1f), 0);
}

TEST(SceneLoader, FullSceneRenderSettings) {
    photon::RenderSettings r = load(fullScene()).render;
    EXPECT_EQ(r.integrator, photon::IntegratorKind::Path);
    EXPECT_EQ(r.passes, 16);
    EXPECT_EQ(r.photonsPerPass, 1000);
    EXPECT_DOUBLE_EQ(r.timeLimitSeconds, 2.5);
    EXPECT_EQ(r.initialRadius, 0);  // "auto"
    EXPECT_FLOAT_EQ(r.alpha, 0.7f);
    EXPECT_EQ(r.maxDepth, 5);
    EXPECT_EQ(r.seed, 42u);
    EXPECT_EQ(r.kernel, photon::KernelKind::Biweight);
    EXPECT_FLOAT_EQ(r.exposure, -1);
    EXPECT_EQ(r.direct, photon::DirectLighting::Photons);
}

TEST(SceneLoader, Defaults) {
    SceneDescription s = load(Json::parse(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40},
      "materials": {"d": {"type": "diffuse"}, "m": {"type": "mirror"}, "g": {"type": "dielectric"},
                    "c": {"type": "conductor"}, "p": {"type": "plastic"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "d"}],
      "lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1]}]
    })"));
    EXPECT_EQ(s.camera.width, 512);
    EXPECT_EQ(s.camera.height, 512);
    EXPECT_VEC3_NEAR(s.camera.up, Vec3(0, 1, 0), 0);
    EXPECT_EQ(s.camera.apertureRadius, 0);
    EXPECT_FLOAT_EQ(s.camera.focusDistance, 5);  // |look_at - position|
    EXPECT_VEC3_NEAR(s.materials[0]->tint().value, Color(0.8f), 0);
    EXPECT_VEC3_NEAR(s.materials[1]->tint().value, Color(1.0f), 0);
    EXPECT_VEC3_NEAR(s.materials[3]->tint().value, Color(0.9f), 0);
    EXPECT_VEC3_NEAR(s.materials[4]->tint().value, Color(0.5f), 0);
    EXPECT_FALSE(s.shapes[0].flipNormals);
    EXPECT_FLOAT_EQ(s.lights[0].coneAngleDegrees, 30);
    EXPECT_FLOAT_EQ(s.lights[0].falloffAngleDegrees, 25);
    photon::RenderSettings r = s.render, d;
    EXPECT_EQ(r.integrator, photon::IntegratorKind::Sppm);
    EXPECT_EQ(r.passes, 64);
    EXPECT_EQ(r.photonsPerPass, 200000);
    EXPECT_EQ(r.timeLimitSeconds, 0);
    EXPECT_EQ(r.initialRadius, 0);
    EXPECT_FLOAT_EQ(r.alpha, d.alpha);
    EXPECT_EQ(r.maxDepth, 8);
    EXPECT_EQ(r.seed, 1u);
    EXPECT_EQ(r.kernel, photon::KernelKind::Uniform);
    EXPECT_EQ(r.exposure, 0);
    EXPECT_EQ(r.direct, photon::DirectLighting::LightSampling);
}

TEST(SceneLoader, NumericInitialRadiusAndBigSeed) {
    Json doc = fullScene();
    doc["render"]["initial_radius"] = 0.01;
    doc["render"]["seed"] = 18446744073709551615ull;
    photon::RenderSettings r = load(doc).render;
    EXPECT_FLOAT_EQ(r.initialRadius, 0.01f);
    EXPECT_EQ(r.seed, 18446744073709551615ull);
}

TEST(SceneLoader, EmissiveShapeAloneLightsTheScene) {
    Json doc = fullScene();
    doc.erase("lights");
    EXPECT_TRUE(load(doc).lights.empty());
}

TEST(SceneLoader, MatrixTransform) {
    Json doc = fullScene();
    // A rotation by 90 degrees about z and a translation, written out.
    doc["shapes"][4]["transform"] = Json::parse(R"({"matrix": [0, -1, 0, 5,  1, 0, 0, 6,  0, 0, 1, 7,  0, 0, 0, 1]})");
    SceneDescription scene = load(doc);
    const auto& m = scene.shapes[4].mesh;
    EXPECT_VEC3_NEAR(m.positions[1], Vec3(5, 7, 7), 1e-6);  // (1, 0, 0) -> (0, 1, 0) + t
    EXPECT_VEC3_NEAR(m.positions[2], Vec3(4, 6, 7), 1e-6);  // (0, 1, 0) -> (-1, 0, 0) + t
}

TEST(SceneLoader, MirroringTransformKeepsWindingConsistent) {
    Json doc = fullScene();
    doc["shapes"][0]["transform"] = Json::parse(R"({"scale": [-1, 1, 1]})");
    SceneDescription scene = load(doc);
    const auto& m = scene.shapes[0].mesh;
    Vec3 p0 = m.positions[m.indices[0]], p1 = m.positions[m.indices[1]], p2 = m.positions[m.indices[2]];
    Vec3 geometric = photon::normalize(photon::cross(p1 - p0, p2 - p0));
    // The floor still faces +y, and the geometric normal agrees with the shading normal.
    EXPECT_VEC3_NEAR(m.normals[0], Vec3(0, 1, 0), 1e-6);
    EXPECT_VEC3_NEAR(geometric, Vec3(0, 1, 0), 1e-6);
}

TEST(SceneLoader, SphereTransformUniformScale) {
    Json doc = fullScene();
    doc["shapes"][3]["transform"] = Json::parse(R"({"scale": 2, "rotate": {"axis": [1, 0, 0], "angle": 90},
                                                    "translate": [0, 0, 1]})");
    SceneDescription scene = load(doc);
    const auto& s = scene.shapes[3];
    EXPECT_FLOAT_EQ(s.radius, 0.6f);
    // (0.4, 0.3, 0.2) * 2 = (0.8, 0.6, 0.4); about x by 90: (x, -z, y) = (0.8, -0.4, 0.6); + (0, 0, 1).
    EXPECT_VEC3_NEAR(s.center, Vec3(0.8f, -0.4f, 1.6f), 1e-6);
}

TEST(SceneLoader, PlyAndGltfMeshes) {
    Json doc = fullScene();
    doc["shapes"][2].erase("transform");
    doc["shapes"][2]["file"] = "meshes/tri.ply";
    auto ply = load(doc).shapes[2].mesh;
    ASSERT_EQ(ply.triangleCount(), 1u);
    EXPECT_VEC3_NEAR(ply.positions[ply.indices[1]], Vec3(2, 0, 0), 0);
    doc["shapes"][2]["file"] = "meshes/tri.gltf";
    auto gltf = load(doc).shapes[2].mesh;
    ASSERT_EQ(gltf.triangleCount(), 1u);
    EXPECT_VEC3_NEAR(gltf.positions[gltf.indices[1]], Vec3(1, 0, 5), 1e-6);  // node translation baked in
    // An external buffer inside the scene folder loads (escape.gltf, whose buffer is
    // outside, is refused in SceneLoaderErrors.UnreadableFiles).
    doc["shapes"][2]["file"] = "meshes/external.gltf";
    EXPECT_EQ(load(doc).shapes[2].mesh.triangleCount(), 1u);
}

TEST(SceneLoader, TexturesAreShared) {
    Json doc = fullScene();
    doc["materials"]["gloss"]["albedo"] = Json::parse(R"({"texture": "textures/wood.png"})");
    SceneDescription s = load(doc);
    EXPECT_EQ(s.materials[1]->tint().texture, s.materials[5]->tint().texture);
}

TEST(SceneLoader, LoadSceneFileResolvesAgainstItsFolder) {
    const fs::path file = fixture().scene / "scene.json";
    writeText(file, kFullScene);
    SceneDescription s = photon::loadSceneFile(file);
    EXPECT_EQ(s.shapes.size(), 6u);
    EXPECT_TRUE(s.materials[1]->tint().textured());
}

// ---- errors: exact messages at exact paths ----

TEST(SceneLoaderErrors, MalformedJson) {
    SceneError e = errorFromText("{\"camera\": {\"fov\": 19.5,}}");
    EXPECT_EQ(e.path(), "");
    EXPECT_EQ(std::string(e.what()).rfind("malformed JSON: parse error at line 1, column 25: syntax error", 0), 0u)
        << e.what();
    EXPECT_EQ(errorFromText("").path(), "");
    EXPECT_EQ(std::string(errorFromText("[1, 2]").what()), "the scene must be a JSON object");
    EXPECT_EQ(std::string(errorFromText(std::string(200, '[') + std::string(200, ']')).what()),
              "malformed JSON: nested deeper than 64 levels");
}

TEST(SceneLoaderErrors, DuplicateField) {
    std::string text = kFullScene;
    text.replace(text.find("\"radius\": 0.3"), 13, "\"radius\": 0.3, \"radius\": 0.4");
    SceneError e = errorFromText(text);
    EXPECT_EQ(std::string(e.what()), "shapes[3].radius: duplicate field");
}

TEST(SceneLoaderErrors, NonFiniteNumbers) {
    std::string text = kFullScene;
    text.replace(text.find("\"radius\": 0.3"), 13, "\"radius\": 1e999");
    SceneError e = errorFromText(text);
    EXPECT_EQ(e.path(), "shapes[3].radius");
    EXPECT_EQ(std::string(e.what()), "shapes[3].radius: must be a finite number");

    text = kFullScene;
    text.replace(text.find("[0.725, 0.71, 0.68]"), 19, "[0.725, -1e999, 0.68]");
    EXPECT_EQ(std::string(errorFromText(text).what()), "materials.white.albedo[1]: must be a finite number");
    // Finite as a double but not as a float.
    expectError([](Json& d) { d["shapes"][3]["center"][0] = 1e300; }, "shapes[3].center[0]", "must be a finite number");
}

TEST(SceneLoaderErrors, MissingRequiredFields) {
    expectError([](Json& d) { d.erase("camera"); }, "camera", "missing required field");
    expectError([](Json& d) { d.erase("materials"); }, "materials", "missing required field");
    expectError([](Json& d) { d.erase("shapes"); }, "shapes", "missing required field");
    expectError([](Json& d) { d["camera"].erase("fov"); }, "camera.fov", "missing required field");
    expectError([](Json& d) { d["shapes"][3].erase("radius"); }, "shapes[3].radius", "missing required field");
    expectError([](Json& d) { d["shapes"][3].erase("material"); }, "shapes[3].material", "missing required field");
    expectError([](Json& d) { d["materials"]["white"].erase("type"); }, "materials.white.type",
                "missing required field");
    expectError([](Json& d) { d["lights"][0].erase("intensity"); }, "lights[0].intensity", "missing required field");
    expectError([](Json& d) { d["shapes"][2]["transform"]["rotate"].erase("angle"); },
                "shapes[2].transform.rotate.angle", "missing required field");
}

TEST(SceneLoaderErrors, RangeChecks) {
    expectError([](Json& d) { d["shapes"][3]["radius"] = -1; }, "shapes[3].radius", "must be > 0");
    expectError([](Json& d) { d["camera"]["resolution"] = {0, 512}; }, "camera.resolution[0]",
                "must be an integer in [1, 16384]");
    expectError([](Json& d) { d["camera"]["resolution"] = {512, 16385}; }, "camera.resolution[1]",
                "must be an integer in [1, 16384]");
    expectError([](Json& d) { d["camera"]["resolution"] = {512}; }, "camera.resolution",
                "must be an array of 2 integers");
    expectError([](Json& d) { d["render"]["alpha"] = 1.5; }, "render.alpha", "must be in (0, 1)");
    expectError([](Json& d) { d["render"]["passes"] = 1.5; }, "render.passes", "must be an integer in [1, 1000000]");
    expectError([](Json& d) { d["render"]["passes"] = 0; }, "render.passes", "must be an integer in [1, 1000000]");
    expectError([](Json& d) { d["render"]["max_depth"] = 1001; }, "render.max_depth", "must be an integer in [1, 1000]");
    expectError([](Json& d) { d["render"]["seed"] = -1; }, "render.seed", "must be an integer >= 0");
    expectError([](Json& d) { d["render"]["time_limit"] = -1; }, "render.time_limit", "must be >= 0");
    expectError([](Json& d) { d["render"]["initial_radius"] = "big"; }, "render.initial_radius",
                "must be \"auto\" or a number > 0");
    expectError([](Json& d) { d["render"]["initial_radius"] = 0; }, "render.initial_radius", "must be > 0");
    expectError([](Json& d) { d["camera"]["fov"] = 180; }, "camera.fov", "must be in (0, 180)");
    expectError([](Json& d) { d["camera"]["aperture_radius"] = -0.1; }, "camera.aperture_radius", "must be >= 0");
    expectError([](Json& d) { d["camera"]["focus_distance"] = 0; }, "camera.focus_distance", "must be > 0");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = {0.5, 1.2, 0.5}; }, "materials.white.albedo[1]",
                "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["metal"]["roughness"] = 2; }, "materials.metal.roughness",
                "must be in [0, 1]");
    expectError([](Json& d) { d["materials"]["glass"]["ior"] = 0; }, "materials.glass.ior", "must be > 0");
    expectError([](Json& d) { d["shapes"][5]["emission"] = {1, -1, 1}; }, "shapes[5].emission[1]", "must be >= 0");
    expectError([](Json& d) { d["lights"][0]["intensity"] = {1, 1, -1}; }, "lights[0].intensity[2]", "must be >= 0");
    expectError([](Json& d) { d["lights"][1]["cone_angle"] = 95; }, "lights[1].cone_angle", "must be in (0, 90]");
    expectError([](Json& d) { d["lights"][1]["falloff_angle"] = 31; }, "lights[1].falloff_angle",
                "must be <= cone_angle");
}

TEST(SceneLoaderErrors, WrongTypes) {
    expectError([](Json& d) { d["shapes"][3]["radius"] = "big"; }, "shapes[3].radius", "must be a number");
    expectError([](Json& d) { d["shapes"][3]["radius"] = true; }, "shapes[3].radius", "must be a number");
    expectError([](Json& d) { d["shapes"][3]["center"] = {1, 2}; }, "shapes[3].center", "must be an array of 3 numbers");
    expectError([](Json& d) { d["shapes"][3]["center"] = {1, "2", 3}; }, "shapes[3].center[1]", "must be a number");
    expectError([](Json& d) { d["shapes"][1]["flip_normals"] = 1; }, "shapes[1].flip_normals", "must be true or false");
    expectError([](Json& d) { d["shapes"][0]["material"] = 3; }, "shapes[0].material", "must be a string");
    expectError([](Json& d) { d["camera"] = Json::array(); }, "camera", "must be an object");
    expectError([](Json& d) { d["shapes"] = Json::object(); }, "shapes", "must be an array");
    expectError([](Json& d) { d["shapes"] = Json::array(); }, "shapes", "must contain at least one shape");
    expectError([](Json& d) { d["lights"] = 1; }, "lights", "must be an array");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = "red"; }, "materials.white.albedo",
                "must be an array of 3 numbers or {\"texture\": \"path\"}");
    expectError([](Json& d) { d["shapes"][2]["transform"]["scale"] = "x"; }, "shapes[2].transform.scale",
                "must be a number or an array of 3 numbers");
}

TEST(SceneLoaderErrors, UnknownNames) {
    expectError([](Json& d) { d["shapes"][0]["material"] = "foo"; }, "shapes[0].material", "unknown material \"foo\"");
    expectError([](Json& d) { d["shapes"][1]["type"] = "cone"; }, "shapes[1].type",
                "unknown type \"cone\" (expected one of quad, sphere, mesh)");
    expectError([](Json& d) { d["lights"][0]["type"] = "area"; }, "lights[0].type",
                "unknown type \"area\" (expected one of point, spot, directional, environment)");
    expectError([](Json& d) { d["materials"]["white"]["type"] = "lambert"; }, "materials.white.type",
                "unknown type \"lambert\" (expected one of diffuse, dielectric, mirror, conductor, plastic)");
    expectError([](Json& d) { d["camera"]["type"] = "orthographic"; }, "camera.type",
                "unknown type \"orthographic\" (expected one of perspective)");
    expectError([](Json& d) { d["render"]["integrator"] = "bdpt"; }, "render.integrator",
                "unknown value \"bdpt\" (expected one of sppm, path)");
    expectError([](Json& d) { d["render"]["kernel"] = "gauss"; }, "render.kernel",
                "unknown value \"gauss\" (expected one of uniform, biweight)");
    expectError([](Json& d) { d["render"]["direct"] = "none"; }, "render.direct",
                "unknown value \"none\" (expected one of light_sampling, photons)");
}

TEST(SceneLoaderErrors, UnknownFieldsAtEveryDepth) {
    expectError([](Json& d) { d["colour"] = 1; }, "colour", "unknown field");
    expectError([](Json& d) { d["render"]["pases"] = 64; }, "render.pases", "unknown field");
    expectError([](Json& d) { d["camera"]["fov_y"] = 20; }, "camera.fov_y", "unknown field");
    expectError([](Json& d) { d["shapes"][2]["colour"] = {1, 0, 0}; }, "shapes[2].colour", "unknown field");
    expectError([](Json& d) { d["shapes"][2]["transform"]["rotate"]["axes"] = {0, 1, 0}; },
                "shapes[2].transform.rotate.axes", "unknown field");
    expectError([](Json& d) { d["materials"]["white"]["albedoo"] = {1, 1, 1}; }, "materials.white.albedoo",
                "unknown field");
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["filter"] = "nearest"; },
                "materials.wood.albedo.filter", "unknown field");
    expectError([](Json& d) { d["lights"][2]["position"] = {0, 1, 0}; }, "lights[2].position", "unknown field");
    // A field of another material or shape type is unknown here too.
    expectError([](Json& d) { d["materials"]["glass"]["roughness"] = 0.1; }, "materials.glass.roughness",
                "unknown field");
    expectError([](Json& d) { d["shapes"][3]["edge_u"] = {1, 0, 0}; }, "shapes[3].edge_u", "unknown field");
}

TEST(SceneLoaderErrors, Geometry) {
    expectError([](Json& d) { d["shapes"][0]["edge_v"] = {0, 0, 4}; }, "shapes[0]",
                "quad has zero area (edge_u and edge_v are parallel or zero)");
    expectError([](Json& d) { d["shapes"][4]["indices"] = {0, 1, 3}; }, "shapes[4].indices[2]",
                "must be an integer in [0, 2]");
    expectError([](Json& d) { d["shapes"][4]["indices"] = {0, 1, -1}; }, "shapes[4].indices[2]",
                "must be an integer in [0, 2]");
    expectError([](Json& d) { d["shapes"][4]["indices"] = {0, 1}; }, "shapes[4].indices",
                "must have a length that is a multiple of 3");
    expectError([](Json& d) { d["shapes"][4]["indices"] = Json::array(); }, "shapes[4].indices",
                "must contain at least one triangle (3 indices)");
    expectError([](Json& d) { d["shapes"][4]["positions"] = Json::array(); }, "shapes[4].positions",
                "must not be empty");
    expectError([](Json& d) { d["shapes"][4]["normals"].erase(2); }, "shapes[4].normals",
                "must have one entry per position (3)");
    expectError([](Json& d) { d["shapes"][4]["normals"][1] = {0, 0, 0}; }, "shapes[4].normals[1]",
                "must not be the zero vector");
    expectError([](Json& d) { d["shapes"][4]["uvs"][0] = {0, 0, 0}; }, "shapes[4].uvs[0]",
                "must be an array of 2 numbers");
    expectError([](Json& d) { d["shapes"][4]["file"] = "meshes/tri.obj"; }, "shapes[4]",
                "a mesh needs exactly one of \"file\" or \"positions\"");
    expectError([](Json& d) { d["shapes"][4].erase("positions"); }, "shapes[4]",
                "a mesh needs exactly one of \"file\" or \"positions\"");
}

TEST(SceneLoaderErrors, Transforms) {
    expectError([](Json& d) { d["shapes"][3]["transform"] = {{"scale", {1, 2, 1}}}; }, "shapes[3].transform",
                "a sphere can only be scaled uniformly (one scale factor for all axes)");
    expectError([](Json& d) { d["shapes"][2]["transform"]["scale"] = 0; }, "shapes[2].transform.scale",
                "must not be 0");
    expectError([](Json& d) { d["shapes"][2]["transform"]["scale"] = {1, 0, 1}; }, "shapes[2].transform.scale[1]",
                "must not be 0");
    expectError([](Json& d) { d["shapes"][2]["transform"]["rotate"]["axis"] = {0, 0, 0}; },
                "shapes[2].transform.rotate.axis", "must not be the zero vector");
    expectError([](Json& d) { d["shapes"][2]["transform"]["matrix"] = Json::array(); }, "shapes[2].transform",
                "use either \"matrix\" or \"scale\"/\"rotate\"/\"translate\", not both");
    expectError(
        [](Json& d) { d["shapes"][4]["transform"] = {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}}}; },
        "shapes[4].transform.matrix", "the last row must be 0, 0, 0, 1");
    expectError([](Json& d) { d["shapes"][4]["transform"] = {{"matrix", {1, 0, 0, 0}}}; },
                "shapes[4].transform.matrix", "must be an array of 16 numbers");
    expectError(
        [](Json& d) { d["shapes"][4]["transform"] = {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1}}}; },
        "shapes[4].transform", "must be invertible (it flattens the shape)");
}

TEST(SceneLoaderErrors, CameraOrientation) {
    expectError([](Json& d) { d["camera"]["up"] = {0, 0, 2}; }, "camera.up", "must not be parallel to the view direction");
    expectError([](Json& d) { d["camera"]["look_at"] = {0, 1, 6.8}; }, "camera.look_at", "must differ from position");
}

TEST(SceneLoaderErrors, Lights) {
    expectError(
        [](Json& d) {
            d.erase("lights");
            d["shapes"][5].erase("emission");
        },
        "lights", "scene has no light (add a light or an emissive shape)");
    expectError(
        [](Json& d) {
            d["lights"] = Json::array();
            d["shapes"][5]["emission"] = {0, 0, 0};
        },
        "lights", "scene has no light (add a light or an emissive shape)");
    expectError([](Json& d) { d["lights"].push_back({{"type", "environment"}, {"radiance", {1, 1, 1}}}); }, "lights[4]",
                "only one environment light is allowed");
    expectError([](Json& d) { d["lights"][2]["direction"] = {0, 0, 0}; }, "lights[2].direction",
                "must not be the zero vector");
}

TEST(SceneLoaderErrors, FilePaths) {
    const std::string inside = "must be a relative path inside the scene folder";
    expectError([](Json& d) { d["shapes"][2]["file"] = "/etc/passwd"; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = "../outside.obj"; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes/../../outside.obj"; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = ""; }, "shapes[2].file", inside);
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes/link.obj"; }, "shapes[2].file", inside);  // symlink
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "/tmp/x.png"; },
                "materials.wood.albedo.texture", inside);
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "textures/../../x.png"; },
                "materials.wood.albedo.texture", inside);
}

TEST(SceneLoaderErrors, UnreadableFiles) {
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes/missing.obj"; }, "shapes[2].file",
                "file not found: meshes/missing.obj");
    expectError([](Json& d) { d["shapes"][2]["file"] = "meshes"; }, "shapes[2].file", "not a regular file: meshes");
    expectError([](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "textures/missing.png"; },
                "materials.wood.albedo.texture", "file not found: textures/missing.png");
    // Invalid contents: the library's reason, without the folder the scene sits in.
    for (auto [edit, path] : std::vector<std::pair<std::function<void(Json&)>, std::string>>{
             {[](Json& d) { d["shapes"][2]["file"] = "meshes/corrupt.obj"; }, "shapes[2].file"},
             {[](Json& d) { d["shapes"][2]["file"] = "meshes/escape.gltf"; }, "shapes[2].file"},
             {[](Json& d) { d["materials"]["wood"]["albedo"]["texture"] = "textures/corrupt.png"; },
              "materials.wood.albedo.texture"}}) {
        Json doc = fullScene();
        edit(doc);
        SceneError e = errorFromText(doc.dump());
        EXPECT_EQ(e.path(), path);
        std::string what = e.what();
        EXPECT_GT(what.size(), path.size() + 2) << what;
        EXPECT_EQ(what.find(fixture().root.string()), std::string::npos) << what;
    }
}

TEST(SceneLoaderErrors, LoadSceneFileUnreadable) {
    const fs::path missing = fixture().scene / "missing.json";
    try {
        photon::loadSceneFile(missing);
        FAIL() << "loaded a missing file";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "");
        EXPECT_EQ(std::string(e.what()), "cannot read scene file \"" + missing.string() + "\": No such file or directory");
    }
    try {
        photon::loadSceneFile(fixture().scene);
        FAIL() << "loaded a directory";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot read scene file \"" + fixture().scene.string() + "\": it is a directory");
    }
}

// Every leaf of the full scene replaced by values of the wrong kind: each load either
// succeeds or throws a SceneError; nothing else escapes and nothing crashes.
TEST(SceneLoaderErrors, MutatedScenesNeverCrash) {
    const Json flat = fullScene().flatten();
    const Json junk[] = {nullptr, "x", -1, 0, 1e30, -1e30, 0.5, true, Json::array(), Json::object(), {1, 2, 3}};
    int errors = 0;
    for (auto it = flat.begin(); it != flat.end(); ++it) {
        for (const Json& j : junk) {
            Json doc = fullScene();
            doc[Json::json_pointer(it.key())] = j;
            try {
                photon::loadSceneJson(doc.dump(), fixture().scene);
            } catch (const SceneError&) {
                ++errors;
            } catch (const std::exception& e) {
                ADD_FAILURE() << it.key() << " = " << j.dump() << ": " << e.what();
            }
        }
    }
    EXPECT_GT(errors, 0);
}

// ---- the example scenes ----

TEST(ExampleScenes, AllLoad) {
    for (const char* name : {"cornell-box.json", "cornell-glass.json", "point-light-plane.json", "textured-mesh.json"}) {
        SCOPED_TRACE(name);
        SceneDescription s = photon::loadSceneFile(photon::test::sourcePath(std::string("scenes/") + name));
        EXPECT_EQ(s.camera.width, 512);
        EXPECT_EQ(s.camera.height, 512);
        EXPECT_EQ(s.render.passes, 64);
        EXPECT_EQ(s.render.photonsPerPass, 200000);
    }
}

TEST(ExampleScenes, CornellBoxLightFacesDown) {
    SceneDescription s = photon::loadSceneFile(photon::test::sourcePath("scenes/cornell-box.json"));
    int emitters = 0;
    for (const auto& shape : s.shapes) {
        if (photon::isBlack(shape.emission)) continue;
        ++emitters;
        const auto& m = shape.mesh;
        EXPECT_VEC3_NEAR(m.normals[0], Vec3(0, -1, 0), 0);
        Vec3 p0 = m.positions[m.indices[0]], p1 = m.positions[m.indices[1]], p2 = m.positions[m.indices[2]];
        EXPECT_VEC3_NEAR(photon::normalize(photon::cross(p1 - p0, p2 - p0)), Vec3(0, -1, 0), 1e-6);
        EXPECT_NEAR(p0.y, 1.98f, 1e-6);
    }
    EXPECT_EQ(emitters, 1);
}

// The uv sphere's triangles are wound outward and its normals point outward.
TEST(ExampleScenes, TexturedMeshIsOutwardFacing) {
    auto mesh = photon::loadMeshFile(photon::test::sourcePath("scenes/meshes/uv-sphere.obj"));
    ASSERT_GT(mesh.triangleCount(), 100u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3 p0 = mesh.positions[mesh.indices[3 * t]], p1 = mesh.positions[mesh.indices[3 * t + 1]],
             p2 = mesh.positions[mesh.indices[3 * t + 2]];
        Vec3 centroid = (p0 + p1 + p2) / 3.0f;
        EXPECT_GT(photon::dot(photon::cross(p1 - p0, p2 - p0), centroid), 0) << "triangle " << t;
    }
}

// ---- textures ----

TEST(Texture, BilinearLookupWithWrapAndBottomRowAtVZero) {
    auto tex = photon::Texture::load(fixture().scene / "textures/wood.png");
    ASSERT_EQ(tex->width(), 2);
    ASSERT_EQ(tex->height(), 2);
    EXPECT_VEC3_NEAR(tex->lookup({0.25f, 0.25f}), Vec3(0, 0, 1), 1e-6);  // bottom left: blue
    EXPECT_VEC3_NEAR(tex->lookup({0.25f, 0.75f}), Vec3(1, 0, 0), 1e-6);  // top left: red
    EXPECT_VEC3_NEAR(tex->lookup({0.75f, 0.75f}), Vec3(0, 1, 0), 1e-6);  // top right: green
    EXPECT_VEC3_NEAR(tex->lookup({0.5f, 0.25f}), Vec3(0.5f, 0.5f, 1), 1e-6);
    // Wrap-around: u = 0 lies halfway between the last and the first column.
    EXPECT_VEC3_NEAR(tex->lookup({0.0f, 0.25f}), Vec3(0.5f, 0.5f, 1), 1e-6);
    EXPECT_VEC3_NEAR(tex->lookup({1.25f, -0.75f}), tex->lookup({0.25f, 0.25f}), 1e-6);
    EXPECT_VEC3_NEAR(tex->lookup({-3.75f, 7.25f}), tex->lookup({0.25f, 0.25f}), 1e-5);
    EXPECT_VEC3_NEAR(tex->average(), Vec3(0.5f, 0.5f, 0.5f), 1e-6);
    Color nan = tex->lookup({std::nanf(""), INFINITY});
    EXPECT_TRUE(photon::isFinite(nan));
}

TEST(Texture, SrgbGreyAlphaAndFloat) {
    const fs::path dir = fixture().scene / "textures";
    writeImage<uint8_t>(dir / "grey.png", 2, 1, 1, OIIO::TypeDesc::UINT8, {128, 10});
    auto grey = photon::Texture::load(dir / "grey.png");
    // The exact sRGB curve: 128/255 -> 0.2158605, and the linear toe 10/255/12.92.
    EXPECT_VEC3_NEAR(grey->lookup({0.25f, 0.5f}), Color(0.2158605f), 1e-6);
    EXPECT_VEC3_NEAR(grey->lookup({0.75f, 0.5f}), Color(10 / 255.0f / 12.92f), 1e-7);

    // Alpha is ignored, and colour is not premultiplied by it.
    writeImage<uint8_t>(dir / "alpha.png", 1, 1, 4, OIIO::TypeDesc::UINT8, {255, 128, 0, 0});
    EXPECT_VEC3_NEAR(photon::Texture::load(dir / "alpha.png")->average(), Vec3(1, 0.2158605f, 0), 1e-6);

    writeImage<uint16_t>(dir / "deep.png", 1, 1, 3, OIIO::TypeDesc::UINT16, {65535, 32768, 0});
    const float half16 = float(std::pow((32768 / 65535.0 + 0.055) / 1.055, 2.4));  // 0.21404
    EXPECT_VEC3_NEAR(photon::Texture::load(dir / "deep.png")->average(), Vec3(1, half16, 0), 1e-6);

    // Float images are linear; negative and NaN texels become 0.
    writeImage<float>(dir / "linear.exr", 2, 1, 3, OIIO::TypeDesc::FLOAT, {2.5f, 0.5f, -1, std::nanf(""), 1, 0});
    auto lin = photon::Texture::load(dir / "linear.exr");
    EXPECT_VEC3_NEAR(lin->lookup({0.25f, 0.5f}), Vec3(2.5f, 0.5f, 0), 1e-6);
    EXPECT_VEC3_NEAR(lin->lookup({0.75f, 0.5f}), Vec3(0, 1, 0), 1e-6);
}

TEST(Texture, TooLargeIsRefused) {
    const fs::path file = fixture().scene / "textures/wide.png";
    writeImage<uint8_t>(file, 16385, 1, 1, OIIO::TypeDesc::UINT8, std::vector<uint8_t>(16385, 0));
    try {
        photon::Texture::load(file);
        FAIL() << "loaded a texture over the limit";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "image is 16385x1, larger than the limit of 16384 pixels a side and 64M pixels in total");
    }
    EXPECT_THROW(photon::Texture::load(fixture().scene / "textures/missing.png"), std::runtime_error);
}

// ---- the JSON reader on its own ----

TEST(JsonReader, PathsAndUnknownFields) {
    photon::Json doc = photon::parseJsonDocument(R"({"a": {"b": [1, {"c": 2, "d": 3}]}})");
    photon::JsonObject top = photon::JsonValue(doc, "").object();
    auto b = top.required("a").object().required("b").elements();
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[1].path(), "a.b[1]");
    photon::JsonObject inner = b[1].object();
    EXPECT_EQ(inner.number("c", 0), 2);
    try {
        inner.finish();
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "a.b[1].d: unknown field");
    }
    EXPECT_EQ(b[0].integer(0, 5), 1);
    EXPECT_THROW(b[0].integer(2, 5), SceneError);
}
