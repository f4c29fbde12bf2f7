// Scenes in the formats the engine imports (pbrt-v4, glTF 2.0) submitted as the "scene" part
// of a multipart upload: stored under their own kind of name, rendered exactly as the engine
// renders the same file in process, the importer's warnings kept with the job, and its
// errors answered with the place in the file.
#include <cstring>
#include <fstream>
#include <photon/render.h>
#include <photon/scene_file.h>
#include "server_fixture.h"

namespace photon::test {
namespace {

namespace fs = std::filesystem;

// A floor and an area light above it, seen from the front; the light comes from an
// included file, the floor from a PLY mesh, both uploaded as parts by their paths.
const std::string kRoomPbrt = R"(LookAt 0 1 4  0 1 0  0 1 0
Camera "perspective" "float fov" [45]
Film "rgb" "integer xresolution" [24] "integer yresolution" [16]
Sampler "halton" "integer pixelsamples" [2]
Integrator "sppm" "integer photonsperiteration" [2000]
PixelFilter "mitchell"
WorldBegin
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "plymesh" "string filename" "meshes/floor.ply"
Include "parts/light.pbrt"
)";

const std::string kLightPbrt = R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [8 8 8]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
    "point3 P" [-0.5 2 -0.5  0.5 2 -0.5  0.5 2 0.5  -0.5 2 0.5]
AttributeEnd
)";

const std::string kFloorPly = R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
-2 0 -2
2 0 -2
2 0 2
-2 0 2
3 0 2 1
3 0 3 2
)";

httplib::MultipartFormDataItems roomParts(const std::string& sceneFileName = "Room.PBRT") {
    return {{"scene", kRoomPbrt, sceneFileName, "text/plain"},
            {"light", kLightPbrt, "parts/light.pbrt", "text/plain"},
            {"floor", kFloorPly, "meshes/floor.ply", "application/octet-stream"}};
}

void writeFile(const fs::path& file, const std::string& bytes) {
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

// The room written to a folder of its own as the server stores it, rendered in process.
Image renderRoomInProcess(uint64_t seed, const std::string& sceneText = kRoomPbrt) {
    const fs::path dir = fs::temp_directory_path() / ("photon-import-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    writeFile(dir / "scene.pbrt", sceneText);
    writeFile(dir / "parts" / "light.pbrt", kLightPbrt);
    writeFile(dir / "meshes" / "floor.ply", kFloorPly);
    SceneFile scene = SceneFile::read(dir / "scene.pbrt");
    scene.render().seed = seed;
    Renderer renderer(std::move(scene));
    CancelToken cancel;
    EXPECT_EQ(renderer.run(cancel), RenderOutcome::Completed);
    Image image = renderer.snapshot();
    fs::remove_all(dir);
    return image;
}

void appendU32(std::string& out, uint32_t value) {
    for (int i = 0; i < 4; ++i) out += char((value >> (8 * i)) & 0xff);
}

// A binary glTF: an emissive quad in the z = 0 plane facing a camera named "Front" on +z.
std::string quadGlb() {
    const float positions[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::string bin(sizeof positions + sizeof indices, '\0');
    std::memcpy(bin.data(), positions, sizeof positions);
    std::memcpy(bin.data() + sizeof positions, indices, sizeof indices);
    json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 1}}}}},
        {"nodes", {{{"mesh", 0}}, {{"camera", 0}, {"translation", {0, 0, 3}}}}},
        {"cameras", {{{"name", "Front"}, {"type", "perspective"},
                      {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"aspectRatio", 1.0}}}}}},
        {"materials", {{{"emissiveFactor", {1, 1, 1}},
                        {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
        {"buffers", {{{"byteLength", bin.size()}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof positions}},
                         {{"buffer", 0}, {"byteOffset", sizeof positions}, {"byteLength", sizeof indices}}}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                        {"min", {-1, -1, 0}}, {"max", {1, 1, 0}}},
                       {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
    };
    std::string text = gltf.dump();
    while (text.size() % 4) text += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string glb = "glTF";
    appendU32(glb, 2);
    appendU32(glb, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    appendU32(glb, uint32_t(text.size()));
    glb += "JSON" + text;
    appendU32(glb, uint32_t(bin.size()));
    glb += std::string("BIN\0", 4) + bin;
    return glb;
}

// The room with its floor's material one photon has no model for.
httplib::MultipartFormDataItems velvetRoomParts() {
    std::string velvet = kRoomPbrt;
    velvet.replace(velvet.find("Material \"diffuse\""), std::strlen("Material \"diffuse\""), "Material \"velvet\"");
    httplib::MultipartFormDataItems items = roomParts();
    items[0].content = velvet;
    return items;
}

using ImportsTest = ServerTest;

TEST_F(ImportsTest, APbrtSceneRendersAsTheEngineRendersItWithItsWarnings) {
    startServer({"--workers", "1"});
    httplib::Result r = client().Post("/api/v1/jobs?seed=7", roomParts());
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json job = json::parse(r->body);
    const std::string id = job["id"];
    EXPECT_EQ(job["name"], "Room");
    EXPECT_EQ(job["warnings"],
              json({"scene.pbrt:6: PixelFilter \"mitchell\": its negative lobes are left out (photon's pixel estimates "
                    "are not negative)"}));
    EXPECT_EQ(job["settings"]["passes"], 2);
    EXPECT_EQ(job["settings"]["photons_per_pass"], 2000);
    EXPECT_EQ(job["settings"]["seed"], 7);
    EXPECT_EQ(job["settings"]["resolution"], json({24, 16}));
    EXPECT_EQ(job["settings"]["camera"], nullptr);
    // Kept under its own kind of name, with every file it came with.
    const fs::path folder = dataDir() / "jobs" / id;
    EXPECT_TRUE(fs::is_regular_file(folder / "scene.pbrt"));
    EXPECT_FALSE(fs::exists(folder / "scene.json"));
    EXPECT_TRUE(fs::is_regular_file(folder / "parts" / "light.pbrt"));
    EXPECT_TRUE(fs::is_regular_file(folder / "meshes" / "floor.ply"));
    httplib::Result scene = client().Get("/api/v1/jobs/" + id + "/scene");
    EXPECT_EQ(scene->body, kRoomPbrt);
    EXPECT_EQ(scene->get_header_value("Content-Type"), "text/plain; charset=utf-8");

    json done = waitForStatus(id, "completed");
    EXPECT_EQ(done["warnings"], job["warnings"]);
    EXPECT_EQ(getJob(id)["warnings"], job["warnings"]);
    Image served = decodeImage(client().Get("/api/v1/jobs/" + id + "/image?format=exr")->body, "exr");
    Image direct = renderRoomInProcess(7);
    ASSERT_EQ(served.rgb.size(), direct.rgb.size());
    size_t differing = 0, lit = 0;
    for (size_t i = 0; i < direct.rgb.size(); ++i) {
        differing += served.rgb[i] != direct.rgb[i];
        lit += direct.rgb[i] > 0;
    }
    EXPECT_EQ(differing, 0u) << "of " << direct.rgb.size() << " channel values";
    EXPECT_GT(lit, 0u);

    // A clone is the same kind of scene, with its files.
    httplib::Result copy = client().Post("/api/v1/jobs/" + id + "/clone?passes=1");
    ASSERT_EQ(copy->status, 201) << copy->body;
    EXPECT_EQ(json::parse(copy->body)["warnings"], job["warnings"]);
    EXPECT_EQ(waitForStatus(json::parse(copy->body)["id"], "completed")["pass"], 1);
}

TEST_F(ImportsTest, ASingleGlbRendersFromTheCameraNamed) {
    startServer({"--workers", "1"});
    const std::string glb = quadGlb();
    httplib::MultipartFormDataItems items{{"scene", glb, "quad.glb", "model/gltf-binary"},
                                          {"camera", "Front", "", ""}};
    httplib::Result r = client().Post("/api/v1/jobs?passes=1&photons_per_pass=1000", items);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json job = json::parse(r->body);
    const std::string id = job["id"];
    EXPECT_EQ(job["settings"]["camera"], "Front");
    EXPECT_EQ(job["settings"]["resolution"], json({720, 720}));
    // Stored byte for byte.
    EXPECT_EQ(client().Get("/api/v1/jobs/" + id + "/scene")->body, glb);
    json done = waitForStatus(id, "completed");
    Image image = decodeImage(client().Get("/api/v1/jobs/" + id + "/image?format=exr")->body, "exr");
    size_t lit = 0;
    for (float v : image.rgb) lit += v > 0;
    EXPECT_GT(lit, image.rgb.size() / 10) << "the quad fills the middle of the view";

    // A camera the file does not have, and a camera for a scene that has only one.
    httplib::MultipartFormDataItems other{{"scene", glb, "quad.glb", "model/gltf-binary"}};
    json missing = problemOf(client().Post("/api/v1/jobs?camera=Side", other));
    EXPECT_EQ(missing["status"], 400);
    EXPECT_NE(missing["error"].get<std::string>().find("Side"), std::string::npos) << missing.dump();
    json single = problemOf(client().Post("/api/v1/jobs?camera=Front", roomParts()));
    EXPECT_EQ(single["error"], "camera: chooses among a glTF scene's cameras; this scene has a single camera");
}

TEST_F(ImportsTest, TheServerLimitsHoldForTheImportedScene) {
    startServer({"--workers", "0", "--max-pixels", "100000"});
    httplib::MultipartFormDataItems items{{"scene", quadGlb(), "quad.glb", ""}};
    json problem = problemOf(client().Post("/api/v1/jobs", items));
    EXPECT_EQ(problem["status"], 422);
    EXPECT_NE(problem["error"].get<std::string>().find("pixel count (720 x 720) is 518400"), std::string::npos) << problem.dump();
    EXPECT_TRUE(fs::is_empty(dataDir() / "jobs"));
}

TEST_F(ImportsTest, ABrokenPbrtSceneIs400WithItsFileAndLine) {
    startServer({"--workers", "0"});
    httplib::MultipartFormDataItems items = velvetRoomParts();
    json problem = problemOf(client().Post("/api/v1/jobs", items));
    EXPECT_EQ(problem["status"], 400);
    EXPECT_EQ(problem["type"], "urn:photon:problem:scene-invalid");
    EXPECT_EQ(problem["path"], "scene.pbrt:8");
    EXPECT_EQ(problem["error"],
              "scene.pbrt:8: material \"velvet\" is not supported (photon imports diffuse, coateddiffuse, dielectric, "
              "thindielectric, conductor, coatedconductor, diffusetransmission, hair, measured, mix, interface, subsurface)");
    EXPECT_FALSE(problem.contains("pointer"));  // not a place in photon's JSON
    // A missing included file: where the Include is.
    items = roomParts();
    items.erase(items.begin() + 1);
    problem = problemOf(client().Post("/api/v1/jobs", items));
    EXPECT_EQ(problem["path"], "scene.pbrt:10");
    EXPECT_EQ(problem["error"], "scene.pbrt:10: Include \"parts/light.pbrt\": file not found");
    EXPECT_TRUE(fs::is_empty(dataDir() / "jobs"));
    EXPECT_TRUE(fs::is_empty(dataDir() / "tmp"));
}

// ?lenient=true: the material photon has no model for becomes grey diffuse, with a warning,
// and the job renders; the setting is kept with the job (a restart imports alike) and shown.
TEST_F(ImportsTest, LenientRendersWhatAStrictImportRefuses) {
    startServer({"--workers", "1"});
    const httplib::MultipartFormDataItems items = velvetRoomParts();
    EXPECT_EQ(problemOf(client().Post("/api/v1/jobs?lenient=false", items))["status"], 400);
    json wrong = problemOf(client().Post("/api/v1/jobs?lenient=yes", items));
    EXPECT_EQ(wrong["status"], 400);
    EXPECT_EQ(wrong["error"], "query parameter lenient: must be true or false");
    httplib::Result r = client().Post("/api/v1/jobs?lenient=true", items);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json job = json::parse(r->body);
    EXPECT_EQ(job["settings"]["lenient"], true);
    ASSERT_EQ(job["warnings"].size(), 2u) << job.dump();
    EXPECT_EQ(job["warnings"][1],
              "scene.pbrt:8: material \"velvet\" is not supported (photon imports diffuse, coateddiffuse, dielectric, "
              "thindielectric, conductor, coatedconductor, diffusetransmission, hair, measured, mix, interface, subsurface); rendered as a grey "
              "diffuse material (lenient import)");
    EXPECT_EQ(waitForStatus(job["id"], "completed")["settings"]["lenient"], true);
    // The same as a form field; the query, where given, wins.
    httplib::MultipartFormDataItems withField = items;
    withField.push_back({"lenient", "true", "", ""});
    r = client().Post("/api/v1/jobs", withField);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    EXPECT_EQ(json::parse(r->body)["settings"]["lenient"], true);
    EXPECT_EQ(problemOf(client().Post("/api/v1/jobs?lenient=false", withField))["status"], 400);
    withField.back().content = "maybe";
    EXPECT_EQ(problemOf(client().Post("/api/v1/jobs", withField))["error"], "form field lenient: must be true or false");
}

// Hair: the room with a few pbrt curves of the hair material over its floor. Their points
// live in memory only (the import's HAIR file): the job renders them, and stores only the
// files uploaded. The image is the in-process render's, bit for bit.
TEST_F(ImportsTest, APbrtSceneWithHairRenders) {
    startServer({"--workers", "1"});
    const std::string hairPbrt = kRoomPbrt + R"(Material "hair" "float eumelanin" [0.3]
Shape "curve" "point3 P" [-0.5 0.2 0  -0.2 0.6 0  0.2 0.6 0  0.5 0.2 0] "float width" [0.02] "string type" "cylinder"
Shape "curve" "string basis" "bspline" "point3 P" [-0.5 0.3 0.2  -0.2 0.7 0.2  0.2 0.7 0.2  0.5 0.3 0.2] "float width" [0.02]
)";
    httplib::MultipartFormDataItems parts = roomParts();
    parts[0].content = hairPbrt;
    httplib::Result r = client().Post("/api/v1/jobs?seed=3", parts);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    const std::string id = json::parse(r->body)["id"];
    EXPECT_EQ(waitForStatus(id, "completed")["pass"], 2);
    EXPECT_FALSE(fs::exists(dataDir() / "jobs" / id / "curves"));
    Image served = decodeImage(client().Get("/api/v1/jobs/" + id + "/image?format=exr")->body, "exr");
    Image direct = renderRoomInProcess(3, hairPbrt);
    EXPECT_TRUE(served.rgb == direct.rgb);
    EXPECT_FALSE(direct.rgb == renderRoomInProcess(3).rgb);  // the hair is in the image
}

TEST_F(ImportsTest, AnUnknownSceneExtensionIs400NamingTheAcceptedOnes) {
    startServer({"--workers", "0"});
    httplib::MultipartFormDataItems unknown{{"scene", kRoomPbrt, "room.obj", "text/plain"}};
    json problem = problemOf(client().Post("/api/v1/jobs", unknown));
    EXPECT_EQ(problem["status"], 400);
    EXPECT_EQ(problem["error"], "scene part (file name \"room.obj\"): expected a .json, .pbrt, .gltf or .glb file");
    // Reserved like scene.json: the service's own names are no asset's.
    httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "scene.json", "application/json"},
                                          {"asset", "x", "scene.glb", "application/octet-stream"}};
    EXPECT_EQ(problemOf(client().Post("/api/v1/jobs", items))["error"],
              "asset name \"scene.glb\" is reserved: part \"asset\" (file name \"scene.glb\")");
    EXPECT_TRUE(fs::is_empty(dataDir() / "jobs"));
}

}  // namespace
}  // namespace photon::test
