// glTF 2.0 import against values worked out by hand: node transforms, meshes reused as
// objects and instances, the camera, KHR_lights_punctual lights, the material mapping,
// embedded images (data: uri and .glb) read from memory with v flipped, alpha masks, the
// errors' messages, and a render of an imported scene against the same scene written by hand.
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <photon/errors.h>
#include "import/gltf/gltf_import.h"
#include "scene/scene.h"
#include "scene_loader_fixture.h"
#include "texture/textures.h"

namespace tinygltf {
std::string base64_encode(unsigned char const* bytes, unsigned int length);  // in libtinygltf
}

namespace photon {
namespace {

using test::Json;
namespace fs = std::filesystem;

const fs::path& folder() {
    static const fs::path dir = [] {
        fs::path d = fs::temp_directory_path() / ("photon-gltf-" + std::to_string(::getpid()));
        fs::remove_all(d);
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A glTF document under construction, its one buffer's bytes kept apart.
struct Gltf {
    Json doc = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", Json::array()}}}},
                {"nodes", Json::array()}, {"meshes", Json::array()}, {"accessors", Json::array()},
                {"bufferViews", Json::array()}};
    std::string bin;

    int view(const std::string& bytes) {
        while (bin.size() % 4) bin.push_back('\0');
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}});
        bin += bytes;
        return int(doc["bufferViews"].size()) - 1;
    }
    template <typename T>
    int accessor(const std::vector<T>& values, const char* type, int componentType, size_t count) {
        int v = view(std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
        doc["accessors"].push_back({{"bufferView", v}, {"componentType", componentType}, {"count", count}, {"type", type}});
        return int(doc["accessors"].size()) - 1;
    }
    // A mesh of one primitive: positions, optional uvs, indices; returns its index.
    int mesh(const std::vector<float>& positions, const std::vector<uint16_t>& indices, int material = -1,
             const std::vector<float>& uvs = {}) {
        Json prim = {{"attributes", {{"POSITION", accessor(positions, "VEC3", 5126, positions.size() / 3)}}},
                     {"indices", accessor(indices, "SCALAR", 5123, indices.size())}};
        if (!uvs.empty()) prim["attributes"]["TEXCOORD_0"] = accessor(uvs, "VEC2", 5126, uvs.size() / 2);
        if (material >= 0) prim["material"] = material;
        doc["meshes"].push_back({{"primitives", {prim}}});
        return int(doc["meshes"].size()) - 1;
    }
    int node(Json n, bool root = true) {
        doc["nodes"].push_back(std::move(n));
        const int i = int(doc["nodes"].size()) - 1;
        if (root) doc["scenes"][0]["nodes"].push_back(i);
        return i;
    }
    void camera(Json node = {{"translation", {0, 0, 5}}}, Json camera = {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}) {
        doc["cameras"].push_back(std::move(camera));
        node["camera"] = int(doc["cameras"].size()) - 1;
        this->node(std::move(node));
    }
    void pointLight(std::vector<double> position = {0, 2, 0}) {
        addLight({{"type", "point"}, {"intensity", 10}});
        node({{"translation", position}, {"extensions", {{"KHR_lights_punctual", {{"light", lights() - 1}}}}}});
    }
    void addLight(Json light) {
        doc["extensionsUsed"] = {"KHR_lights_punctual"};
        doc["extensions"]["KHR_lights_punctual"]["lights"].push_back(std::move(light));
    }
    int lights() const { return int(doc["extensions"]["KHR_lights_punctual"]["lights"].size()); }
    int material(Json m) {
        doc["materials"].push_back(std::move(m));
        return int(doc["materials"].size()) - 1;
    }
    int image(const std::string& png) {  // embedded by a data: uri
        doc["images"].push_back({{"uri", "data:image/png;base64," +
                                              tinygltf::base64_encode(reinterpret_cast<const unsigned char*>(png.data()), png.size())}});
        doc["textures"].push_back({{"source", int(doc["images"].size()) - 1}});
        return int(doc["textures"].size()) - 1;
    }

    fs::path writeGltf(const std::string& name) {
        Json d = doc;
        d["buffers"] = {{{"byteLength", bin.size()},
                         {"uri", "data:application/octet-stream;base64," +
                                     tinygltf::base64_encode(reinterpret_cast<const unsigned char*>(bin.data()), bin.size())}}};
        test::writeText(folder() / name, d.dump());
        return folder() / name;
    }
    // glTF 2.0 sec. 4.4: a 12-byte header, the JSON chunk, the BIN chunk, each padded to 4.
    fs::path writeGlb(const std::string& name) {
        Json d = doc;
        d["buffers"] = {{{"byteLength", bin.size()}}};
        std::string json = d.dump(), data = bin;
        while (json.size() % 4) json.push_back(' ');
        while (data.size() % 4) data.push_back('\0');
        std::string out;
        auto u32 = [&out](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
        out += "glTF";
        u32(2);
        u32(uint32_t(12 + 8 + json.size() + 8 + data.size()));
        u32(uint32_t(json.size()));
        out += "JSON" + json;
        u32(uint32_t(data.size()));
        out += std::string("BIN\0", 4) + data;
        test::writeText(folder() / name, out);
        return folder() / name;
    }
};

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};
// The unit square in z = 0 facing +z, glTF uvs: v = 0 at the top (y = 1).
const std::vector<float> kSquare = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<float> kSquareUvs = {0, 1, 1, 1, 1, 0, 0, 0};
const std::vector<uint16_t> kSquareIndices = {0, 1, 2, 0, 2, 3};

// A scene with the camera and a point light around what the test adds.
Gltf lit() {
    Gltf g;
    g.camera();
    g.pointLight();
    return g;
}

ImportedScene import(Gltf g, const std::string& name = "scene.gltf", const GltfImportOptions& options = {}) {
    return importGltf(g.writeGltf(name), options);
}

SceneDescription load(const ImportedScene& s) { return loadImportedScene(s, folder()); }

void expectNear(Vec3 a, Vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

// A 1 x 2 PNG: top texel red, bottom green (8-bit sRGB, so 255 and 0 are exact).
std::string redOverGreenPng() {
    const fs::path p = folder() / "red-over-green.png";
    test::writeImage<uint8_t>(p, 1, 2, 3, {255, 0, 0, 0, 255, 0});
    return readBytes(p);
}

TEST(GltfImport, NestedNodeTransformsPlaceTheTriangle) {
    Gltf g = lit();
    const int mesh = g.mesh(kTriangle, {0, 1, 2});
    const double h = std::sqrt(0.5);
    // Parent: translate (1, 2, 3) after a quarter turn about +y; child: scale 2.
    const int child = g.node({{"mesh", mesh}, {"scale", {2, 2, 2}}}, false);
    g.node({{"translation", {1, 2, 3}}, {"rotation", {0, h, 0, h}}, {"children", {child}}});
    const ImportedScene s = import(g);
    ASSERT_EQ(s.document["shapes"].size(), 1u);
    EXPECT_EQ(s.document["shapes"][0]["file"], "meshes/0-0.ply");
    EXPECT_TRUE(s.meshes.count("meshes/0-0.ply"));
    const SceneDescription d = load(s);
    ASSERT_EQ(d.shapes.size(), 1u);
    // (0,0,0) -> (1,2,3); (1,0,0) -> 2x -> (2,0,0) -> turned to (0,0,-2) -> (1,2,1); (0,1,0) -> (1,4,3).
    expectNear(d.shapes[0].mesh.positions[0], {1, 2, 3});
    expectNear(d.shapes[0].mesh.positions[1], {1, 2, 1});
    expectNear(d.shapes[0].mesh.positions[2], {1, 4, 3});
}

TEST(GltfImport, MeshUsedTwiceIsOneObjectPlacedTwice) {
    Gltf g = lit();
    const int mesh = g.mesh(kTriangle, {0, 1, 2});
    g.node({{"mesh", mesh}, {"translation", {-2, 0, 0}}});
    g.node({{"mesh", mesh}, {"translation", {3, 0, 0}}});
    const ImportedScene s = import(g);
    ASSERT_TRUE(s.document["objects"].contains("mesh-0"));
    EXPECT_EQ(s.document["objects"]["mesh-0"]["shapes"].size(), 1u);
    ASSERT_EQ(s.document["shapes"].size(), 2u);
    EXPECT_EQ(s.document["shapes"][0]["type"], "instance");
    const SceneDescription d = load(s);
    ASSERT_EQ(d.objects.size(), 1u);
    ASSERT_EQ(d.instances.size(), 2u);
    EXPECT_TRUE(d.shapes.empty());
    expectNear(d.instances[0].toWorld.point({1, 0, 0}), {-1, 0, 0});
    expectNear(d.instances[1].toWorld.point({1, 0, 0}), {4, 0, 0});
}

TEST(GltfImport, CameraFromItsNode) {
    Gltf g;
    const double h = std::sqrt(0.5);
    g.camera({{"translation", {0, 1, 5}}, {"rotation", {0, h, 0, h}}},
             {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.5}, {"znear", 0.1}}}});
    g.pointLight();
    g.node({{"mesh", g.mesh(kTriangle, {0, 1, 2})}});
    const ImportedScene s = import(g);
    const Json& c = s.document["camera"];
    EXPECT_NEAR(c["fov"].get<double>(), 0.8 * 180 / std::numbers::pi, 1e-9);
    EXPECT_EQ(c["resolution"], Json({1080, 720}));
    const SceneDescription d = load(s);
    expectNear(d.camera.position, {0, 1, 5});
    // -Z turned a quarter about +y is -X.
    expectNear(d.camera.lookAt, {-1, 1, 5});
    expectNear(d.camera.up, {0, 1, 0});
    EXPECT_EQ(d.camera.width, 1080);
    EXPECT_EQ(d.camera.height, 720);
}

TEST(GltfImport, CameraChosenByNameOrNamedWhenMissing) {
    Gltf g = lit();
    g.doc["cameras"][0]["name"] = "front";
    g.camera({{"translation", {0, 0, -5}}}, {{"type", "perspective"}, {"name", "back"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
    g.node({{"mesh", g.mesh(kTriangle, {0, 1, 2})}});
    const ImportedScene s = import(g, "named.gltf", {"back"});
    EXPECT_EQ(s.document["camera"]["position"], Json({0.0, 0.0, -5.0}));
    EXPECT_EQ(s.document["camera"]["resolution"], Json({1280, 720}));  // no aspect ratio
    EXPECT_EQ(errorOf([&] { import(g, "named.gltf", {"side"}); }),
              "named.gltf: no camera named \"side\" (the scene's cameras: \"front\", \"back\")");
}

TEST(GltfImport, PunctualLights) {
    Gltf g;
    g.camera();
    g.node({{"mesh", g.mesh(kTriangle, {0, 1, 2})}});
    g.addLight({{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 4}, {"range", 10}});
    g.addLight({{"type", "spot"}, {"intensity", 2}, {"spot", {{"innerConeAngle", std::numbers::pi / 8}, {"outerConeAngle", std::numbers::pi / 4}}}});
    g.addLight({{"type", "directional"}, {"intensity", 3}});
    const double h = std::sqrt(0.5);
    auto placing = [](int light) { return Json{{"KHR_lights_punctual", {{"light", light}}}}; };
    g.node({{"translation", {1, 2, 3}}, {"extensions", placing(0)}});
    g.node({{"translation", {0, 4, 0}}, {"rotation", {-h, 0, 0, h}}, {"extensions", placing(1)}});
    g.node({{"rotation", {-h, 0, 0, h}}, {"extensions", placing(2)}});
    const ImportedScene s = import(g);
    const Json& l = s.document["lights"];
    ASSERT_EQ(l.size(), 3u);
    EXPECT_EQ(l[0]["type"], "point");
    EXPECT_EQ(l[0]["intensity"], Json({4.0, 2.0, 1.0}));
    EXPECT_EQ(l[0]["position"], Json({1.0, 2.0, 3.0}));
    EXPECT_EQ(l[1]["type"], "spot");
    EXPECT_NEAR(l[1]["cone_angle"].get<double>(), 45, 1e-9);
    EXPECT_NEAR(l[1]["falloff_angle"].get<double>(), 22.5, 1e-9);
    EXPECT_EQ(l[2]["type"], "directional");
    EXPECT_EQ(l[2]["irradiance"], Json({3.0, 3.0, 3.0}));
    const SceneDescription d = load(s);
    ASSERT_EQ(d.lights.size(), 3u);
    expectNear(d.lights[1].direction, {0, -1, 0});  // -Z turned a quarter about -x points down
    expectNear(d.lights[2].direction, {0, -1, 0});
    expectNear(d.lights[1].position, {0, 4, 0});
    EXPECT_NE(std::find(s.warnings.begin(), s.warnings.end(),
                        "scene.gltf: /extensions/KHR_lights_punctual/lights/0/range: ignored: photon's lights fall off "
                        "with the inverse square alone"),
              s.warnings.end());
}

TEST(GltfImport, MaterialMapping) {
    Gltf g = lit();
    auto pbr = [](double metallic, double roughness) {
        return Json{{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"metallicFactor", metallic}, {"roughnessFactor", roughness}};
    };
    const int mixed = g.material({{"pbrMetallicRoughness", pbr(0.3, 0.4)}, {"extensions", {{"KHR_materials_ior", {{"ior", 1.4}}}}}});
    const int metal = g.material({{"pbrMetallicRoughness", pbr(1, 0.2)}});
    const int pane = g.material({{"pbrMetallicRoughness", pbr(0, 0)}, {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}});
    const int solid = g.material({{"pbrMetallicRoughness", pbr(0, 0)},
                                  {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                                                  {"KHR_materials_volume", {{"thicknessFactor", 0.1}, {"attenuationDistance", 2},
                                                                            {"attenuationColor", {0.5, 1, 0.25}}}}}}});
    const int lamp = g.material({{"emissiveFactor", {1, 0.5, 0}}, {"doubleSided", true},
                                 {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5}}}, {"EXT_sheen_made_up", Json::object()}}}});
    for (int m : {mixed, metal, pane, solid, lamp}) g.node({{"mesh", g.mesh(kTriangle, {0, 1, 2}, m)}});
    const ImportedScene s = import(g);
    const Json& mats = s.document["materials"];
    const Json& mix = mats["material-0"];
    EXPECT_EQ(mix["type"], "mix");
    EXPECT_EQ(mix["amount"], 0.3);
    EXPECT_EQ(mix["materials"][0],
              Json({{"type", "coated_diffuse"}, {"albedo", {0.5, 0.25, 1.0}}, {"ior", 1.4}, {"roughness", 0.4}}));
    EXPECT_EQ(mix["materials"][1], Json({{"type", "conductor"}, {"reflectance", {0.5, 0.25, 1.0}}, {"roughness", 0.4}}));
    EXPECT_EQ(mats["material-1"], Json({{"type", "conductor"}, {"reflectance", {0.5, 0.25, 1.0}}, {"roughness", 0.2}}));
    EXPECT_EQ(mats["material-2"], Json({{"type", "dielectric"}, {"ior", 1.5}, {"roughness", 0.0}, {"thin", true}}));
    EXPECT_EQ(mats["material-3"], Json({{"type", "dielectric"}, {"ior", 1.5}, {"roughness", 0.0}}));
    // Its volume's attenuation: the medium inside, absorption = -ln(colour) / distance.
    EXPECT_EQ(s.document["shapes"][3]["medium"], Json({{"inside", "material-3"}}));
    const Json& absorption = s.document["media"]["material-3"]["absorption"];
    EXPECT_NEAR(absorption[0].get<double>(), std::log(2.0) / 2, 1e-12);
    EXPECT_EQ(absorption[1].get<double>(), 0.0);
    EXPECT_NEAR(absorption[2].get<double>(), std::log(4.0) / 2, 1e-12);
    EXPECT_FALSE(s.document["shapes"][2].contains("medium"));
    const Json& lampShape = s.document["shapes"][4];
    EXPECT_EQ(lampShape["emission"], Json({1.0, 0.5, 0.0}));
    EXPECT_EQ(lampShape["emission_scale"], 5.0);
    EXPECT_EQ(lampShape["two_sided"], true);
    EXPECT_NE(std::find(s.warnings.begin(), s.warnings.end(),
                        "scene.gltf: /materials/4/extensions/EXT_sheen_made_up: unknown material extension ignored"),
              s.warnings.end());
    const SceneDescription d = load(s);
    EXPECT_FLOAT_EQ(d.shapes[4].emission.x, 5.0f);
    EXPECT_TRUE(d.shapes[4].twoSidedEmission);
}

// KHR_materials_clearcoat on a metal: photon's coated_conductor (ior 1.5, the coat's
// roughness), mixed with the bare metal by clearcoatFactor; on a non-metal it is warned.
TEST(GltfImport, ClearcoatOnAMetal) {
    Gltf g = lit();
    auto coat = [](double factor, double roughness) {
        return Json{{"KHR_materials_clearcoat", {{"clearcoatFactor", factor}, {"clearcoatRoughnessFactor", roughness}}}};
    };
    const Json pbr = {{"baseColorFactor", {0.9, 0.1, 0.1, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0.5}};
    const int paint = g.material({{"pbrMetallicRoughness", pbr}, {"extensions", coat(1, 0.1)}});
    const int half = g.material({{"pbrMetallicRoughness", pbr}, {"extensions", coat(0.5, 0)}});
    const int plastic = g.material({{"pbrMetallicRoughness", {{"metallicFactor", 0}}}, {"extensions", coat(1, 0)}});
    for (int m : {paint, half, plastic}) g.node({{"mesh", g.mesh(kTriangle, {0, 1, 2}, m)}});
    const ImportedScene s = import(g);
    const Json& mats = s.document["materials"];
    const Json metal = {{"reflectance", {0.9, 0.1, 0.1}}, {"roughness", 0.5}};
    EXPECT_EQ(mats["material-0"], Json({{"type", "coated_conductor"}, {"ior", 1.5}, {"roughness", 0.1}, {"conductor", metal}}));
    EXPECT_EQ(mats["material-1"]["type"], "mix");
    EXPECT_EQ(mats["material-1"]["amount"], 0.5);
    EXPECT_EQ(mats["material-1"]["materials"][0],
              Json({{"type", "conductor"}, {"reflectance", {0.9, 0.1, 0.1}}, {"roughness", 0.5}}));
    EXPECT_EQ(mats["material-1"]["materials"][1]["type"], "coated_conductor");
    EXPECT_EQ(mats["material-2"]["type"], "coated_diffuse");
    EXPECT_NE(std::find(s.warnings.begin(), s.warnings.end(),
                        "scene.gltf: /materials/2/extensions/KHR_materials_clearcoat: a clear coat over a non-metal is "
                        "left out (photon's coated_diffuse has one coat)"),
              s.warnings.end());
    load(s);  // and the loader takes what the importer wrote
}

// What the emission texture shows at the quad's point (x, y), found by a ray.
Color emissionAt(const SceneDescription& d, float x, float y) {
    auto scene = Scene::build(d);
    SurfaceHit hit;
    EXPECT_TRUE(scene->intersect(Ray{{x, y, 1}, {0, 0, -1}}, hit));
    return d.shapes[hit.shape].emissionAt({hit.uv, hit.p});
}

Gltf emissiveSquare(int texture, Gltf g) {
    const int m = g.material({{"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", texture}}}});
    g.node({{"mesh", g.mesh(kSquare, kSquareIndices, m, kSquareUvs)}});
    return g;
}

TEST(GltfImport, EmbeddedImageReadFromMemoryTheRightWayUp) {
    Gltf g;
    g.camera();
    const std::string png = redOverGreenPng();
    const int texture = g.image(png);
    g = emissiveSquare(texture, g);
    const ImportedScene s = import(g, "image.gltf");
    ASSERT_TRUE(s.files.count("textures/0.png"));
    EXPECT_EQ(s.files.at("textures/0.png"), png);
    EXPECT_EQ(s.document["shapes"][0]["emission"], Json({{"texture", "textures/0.png"}}));
    const SceneDescription d = load(s);
    // The image's top row (red) is at the top of the square, where glTF's v is 0.
    expectNear(emissionAt(d, 0.5f, 0.75f), {1, 0, 0});
    expectNear(emissionAt(d, 0.5f, 0.25f), {0, 1, 0});
}

TEST(GltfImport, GlbWithBufferViewImage) {
    Gltf g;
    g.camera();
    const std::string png = redOverGreenPng();
    g.doc["images"].push_back({{"bufferView", g.view(png)}, {"mimeType", "image/png"}});
    g.doc["textures"].push_back({{"source", 0}});
    g = emissiveSquare(0, g);
    const ImportedScene s = importGltf(g.writeGlb("scene.glb"));
    ASSERT_TRUE(s.files.count("textures/0.png"));
    EXPECT_EQ(s.files.at("textures/0.png"), png);
    const SceneDescription d = load(s);
    expectNear(emissionAt(d, 0.5f, 0.75f), {1, 0, 0});
    expectNear(emissionAt(d, 0.5f, 0.25f), {0, 1, 0});
}

TEST(GltfImport, PackedMetallicRoughnessReadsItsChannels) {
    Gltf g = lit();
    const int t = g.image(redOverGreenPng());
    const int m = g.material({{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", t}}}, {"roughnessFactor", 0.5}}}});
    g.node({{"mesh", g.mesh(kSquare, kSquareIndices, m, kSquareUvs)}});
    const ImportedScene s = import(g);
    const Json& mix = s.document["materials"]["material-0"];
    EXPECT_EQ(mix["amount"], Json({{"texture", "textures/0.png"}, {"channel", "b"}}));
    const Json roughness = {{"type", "product"}, {"a", {{"texture", "textures/0.png"}, {"channel", "g"}}}, {"b", 0.5}};
    EXPECT_EQ(mix["materials"][1]["roughness"], roughness);
    // The non-metal share's coat takes the same roughness map (a textured coated_diffuse).
    EXPECT_EQ(mix["materials"][0]["roughness"], roughness);
    EXPECT_TRUE(std::none_of(s.warnings.begin(), s.warnings.end(),
                             [](const std::string& w) { return w.find("metallicRoughnessTexture") != std::string::npos; }));
    EXPECT_NO_THROW(load(s));
}

TEST(GltfImport, AlphaMaskBecomesCutoff) {
    Gltf g = lit();
    const int t = g.image(redOverGreenPng());
    const int m = g.material({{"alphaMode", "MASK"}, {"alphaCutoff", 0.4}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", t}}}}}});
    g.node({{"mesh", g.mesh(kSquare, kSquareIndices, m, kSquareUvs)}});
    const ImportedScene s = import(g);
    const Json& shape = s.document["shapes"][0];
    EXPECT_EQ(shape["alpha"], Json({{"texture", "textures/0.png"}, {"channel", "a"}}));
    EXPECT_EQ(shape["alpha_cutoff"], 0.4);
    const SceneDescription d = load(s);
    EXPECT_FLOAT_EQ(d.shapes[0].alphaCutoff, 0.4f);
    EXPECT_TRUE(d.shapes[0].alpha.textured());
}

TEST(GltfImport, Errors) {
    Gltf noCamera;
    noCamera.pointLight();
    noCamera.node({{"mesh", noCamera.mesh(kTriangle, {0, 1, 2})}});
    EXPECT_EQ(errorOf([&] { import(noCamera); }),
              "scene.gltf: the glTF has no camera (no node of its scene has a \"camera\"); photon needs one to render from");

    // An orthographic camera: its view 2 ymag high, xmag / ymag wide; without magnification, refused.
    Gltf ortho;
    ortho.camera({{"translation", {0, 0, 5}}}, {{"type", "orthographic"}, {"orthographic", {{"xmag", 2}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
    ortho.pointLight();
    ortho.node({{"mesh", ortho.mesh(kTriangle, {0, 1, 2})}});
    const Json camera = import(ortho).document["camera"];
    EXPECT_EQ(camera["type"], "orthographic");
    EXPECT_EQ(camera["view_height"], 2.0);
    EXPECT_EQ(camera["resolution"], Json({1440, 720}));
    EXPECT_FALSE(camera.contains("fov"));
    ortho.doc["cameras"][0]["orthographic"]["ymag"] = 0;
    EXPECT_EQ(errorOf([&] { import(ortho); }),
              "scene.gltf: /cameras/0/orthographic: xmag and ymag must be > 0 for photon (the view's half width and height)");

    Gltf dark;
    dark.camera();
    dark.node({{"mesh", dark.mesh(kTriangle, {0, 1, 2})}});
    EXPECT_EQ(errorOf([&] { import(dark); }),
              "scene.gltf: the scene has no light: no node places a KHR_lights_punctual light and no material is emissive");

    Gltf required = lit();
    required.node({{"mesh", required.mesh(kTriangle, {0, 1, 2})}});
    required.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    required.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_draco_mesh_compression"};
    EXPECT_EQ(errorOf([&] { import(required); }),
              "scene.gltf: /extensionsRequired/0: the glTF requires KHR_draco_mesh_compression, which photon does not "
              "support (supported: KHR_lights_punctual, KHR_materials_emissive_strength, KHR_materials_ior, "
              "KHR_materials_transmission, KHR_materials_volume, KHR_texture_transform)");

    Gltf lying = lit();
    lying.node({{"mesh", lying.mesh(kTriangle, {0, 1, 2})}});
    lying.doc["accessors"][0]["count"] = 30;  // the view holds 3 positions
    EXPECT_EQ(errorOf([&] { import(lying); }), "scene.gltf: /accessors/0: needs 360 bytes of bufferView 0, which has 36");

    Gltf badIndex = lit();
    badIndex.node({{"mesh", badIndex.mesh(kTriangle, {0, 1, 7})}});
    EXPECT_EQ(errorOf([&] { import(badIndex); }), "scene.gltf: /accessors/1: index 2 (7) is not below POSITION's 3 vertices");
}

TEST(GltfImport, SparseAccessorAndTriangleStrip) {
    Gltf g = lit();
    const int mesh = g.mesh(kTriangle, {0, 1, 2});
    // Vertex 2 replaced by (0, 3, 0) (sec. 3.6.2.3).
    const int at = g.view(std::string("\x02\x00", 2));
    const std::vector<float> moved = {0, 3, 0};
    const int values = g.view(std::string(reinterpret_cast<const char*>(moved.data()), 12));
    g.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", at}, {"componentType", 5123}}},
                                       {"values", {{"bufferView", values}}}};
    g.node({{"mesh", mesh}});
    // A strip of four vertices without indices: triangles (0, 1, 2) and (1, 3, 2).
    const std::vector<float> strip = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    Json primitive = {{"attributes", {{"POSITION", g.accessor(strip, "VEC3", 5126, 4)}}}, {"mode", 5}};
    g.doc["meshes"].push_back({{"primitives", Json::array({primitive})}});
    g.node({{"mesh", 1}});
    const SceneDescription d = load(import(g));
    expectNear(d.shapes[0].mesh.positions[2], {0, 3, 0});
    EXPECT_EQ(d.shapes[1].mesh.indices, std::vector<uint32_t>({0, 1, 2, 1, 3, 2}));
}

TEST(GltfImport, TextureTransformKeepsTheFlip) {
    Gltf g;
    g.camera();
    const int texture = g.image(redOverGreenPng());
    g = emissiveSquare(texture, g);
    // glTF reads t = 0.5 v + 0.5: the image's lower half (green) over the whole square.
    g.doc["materials"][0]["emissiveTexture"]["extensions"] = {
        {"KHR_texture_transform", {{"scale", {1, 0.5}}, {"offset", {0, 0.5}}}}};
    const ImportedScene s = import(g);
    EXPECT_EQ(s.document["shapes"][0]["emission"]["uv_scale"], Json({1.0, 0.5}));
    EXPECT_EQ(s.document["shapes"][0]["emission"]["uv_offset"], Json({0.0, 0.0}));
    expectNear(emissionAt(load(s), 0.5f, 0.5f), {0, 1, 0});
}

// A rotation too (22.5 degrees, as the Khronos TextureTransformTest model), with an uneven
// scale and an offset: the uv photon looks up is, at every point, the glTF lookup
// uv' = T R S uv with R = [cos sin; -sin cos] in glTF's top-down v (glTF issue 1563),
// carried into photon's v (1 - v).
TEST(GltfImport, TextureTransformRotates) {
    Gltf g;
    g.camera();
    const int texture = g.image(redOverGreenPng());
    g = emissiveSquare(texture, g);
    const double angle = 0.392699, su = 1.5, sv = 0.75, ou = 0.2, ov = 0.1;
    g.doc["materials"][0]["emissiveTexture"]["extensions"] = {
        {"KHR_texture_transform", {{"scale", {su, sv}}, {"offset", {ou, ov}}, {"rotation", angle}}}};
    const ImportedScene s = import(g);
    const Json& e = s.document["shapes"][0]["emission"];
    UvMapping m;
    m.scale = {e["uv_scale"][0].get<float>(), e["uv_scale"][1].get<float>()};
    m.offset = {e["uv_offset"][0].get<float>(), e["uv_offset"][1].get<float>()};
    m.rotation = e["uv_rotation"].get<float>() * 3.14159265f / 180;
    for (Vec2 p : {Vec2{0, 0}, Vec2{1, 0}, Vec2{0.3f, 0.8f}, Vec2{0.9f, 0.4f}}) {
        const double gu = p.x, gv = 1 - p.y;
        const double x = su * gu, y = sv * gv;
        const double lu = std::cos(angle) * x + std::sin(angle) * y + ou, lv = -std::sin(angle) * x + std::cos(angle) * y + ov;
        const Vec2 q = m.apply(p);
        EXPECT_NEAR(q.x, lu, 1e-5) << p.x << ", " << p.y;
        EXPECT_NEAR(q.y, 1 - lv, 1e-5) << p.x << ", " << p.y;
    }
    EXPECT_NO_THROW(load(s));
}

TEST(GltfImport, ImageUriMustStayInsideTheFolder) {
    Gltf g = lit();
    g.doc["images"].push_back({{"uri", "../outside.png"}});
    g.doc["textures"].push_back({{"source", 0}});
    const int m = g.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    g.node({{"mesh", g.mesh(kSquare, kSquareIndices, m, kSquareUvs)}});
    EXPECT_EQ(errorOf([&] { import(g); }), "scene.gltf: /images/0/uri: must be a relative path inside the glTF's folder");
}

// An emissive quad over a diffuse floor, imported and written by hand: the same triangles,
// materials and camera, so SPPM's image is the same to the bit.
TEST(GltfImport, RenderMatchesTheSameSceneWrittenByHand) {
    Gltf g;
    g.camera({{"translation", {0, 1, 3}}});
    const std::vector<float> floor = {-1, 0, 1, 1, 0, 1, 1, 0, -1, -1, 0, -1};
    const std::vector<float> lamp = {-0.3f, 1.5f, -0.3f, 0.3f, 1.5f, -0.3f, 0.3f, 1.5f, 0.3f, -0.3f, 1.5f, 0.3f};
    const int white = g.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 0}}}});
    const int light = g.material({{"emissiveFactor", {1, 1, 1}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}});
    g.node({{"mesh", g.mesh(floor, kSquareIndices, white)}});
    g.node({{"mesh", g.mesh(lamp, kSquareIndices, light)}});
    ImportedScene s = import(g, "render.gltf");
    s.document["render"] = {{"passes", 4}, {"photons_per_pass", 20000}, {"seed", 3}};
    s.document["camera"]["resolution"] = {32, 24};

    auto inlineMesh = [](const std::vector<float>& p, const char* material) {
        Json positions = Json::array();
        for (size_t i = 0; i < p.size(); i += 3) positions.push_back({p[i], p[i + 1], p[i + 2]});
        return Json{{"type", "mesh"}, {"positions", positions}, {"indices", {0, 1, 2, 0, 2, 3}}, {"material", material}};
    };
    Json lampShape = inlineMesh(lamp, "lamp");
    lampShape["emission"] = {1, 1, 1};
    lampShape["emission_scale"] = 4;
    const Json byHand = {
        {"camera", {{"position", {0, 1, 3}}, {"look_at", {0, 1, 2}}, {"up", {0, 1, 0}}, {"fov", 0.8 * 180 / std::numbers::pi},
                    {"resolution", {32, 24}}}},
        {"materials", {{"white", {{"type", "coated_diffuse"}, {"albedo", {0.8, 0.8, 0.8}}, {"ior", 1.5}, {"roughness", 1}}},
                       {"lamp", {{"type", "conductor"}, {"reflectance", {1, 1, 1}}, {"roughness", 1}}}}},
        {"shapes", {inlineMesh(floor, "white"), lampShape}},
        {"render", {{"passes", 4}, {"photons_per_pass", 20000}, {"seed", 3}}}};
    const Image imported = test::renderImage(load(s));
    const Image handWritten = test::renderImage(loadSceneJson(byHand.dump(), folder()));
    ASSERT_EQ(imported.width, handWritten.width);
    double sum = 0;
    size_t differ = 0;
    for (int y = 0; y < imported.height; ++y)
        for (int x = 0; x < imported.width; ++x) {
            sum += luminance(handWritten.at(x, y));
            differ += !(imported.at(x, y) == handWritten.at(x, y));
        }
    EXPECT_GT(sum, 0);
    EXPECT_EQ(differ, 0u);
}

}  // namespace
}  // namespace photon
