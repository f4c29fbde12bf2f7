// Every limit on what costs memory or time answers with its status, a message naming the
// value, the limit and its option, and (for capacity) Retry-After.
#include <unistd.h>
#include <atomic>
#include <fstream>
#include <thread>
#include <photon/image_io.h>
#include <photon/scene_file.h>
#include "server_fixture.h"

namespace photon::test {
namespace {

class LimitsTest : public ServerTest {
protected:
    // Expects `status` and exactly `message` as the error.
    void expectError(const httplib::Result& r, int status, const std::string& message) {
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, status) << r->body;
        EXPECT_EQ(json::parse(r->body).value("error", ""), message);
    }
    httplib::Result postMultipart(const json& scene, const std::string& file, const std::string& bytes) {
        httplib::MultipartFormDataItems items{{"scene", scene.dump(), "", "application/json"},
                                              {"asset", bytes, file, "application/octet-stream"}};
        return client().Post("/api/v1/jobs", items);
    }
};

int64_t trianglesOf(const json& scene) {
    return SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR).triangleCount();
}

// An OBJ strip of `n` triangles.
std::string objStrip(int n) {
    std::string obj;
    for (int i = 0; i <= n + 1; ++i)
        obj += "v " + std::to_string(0.01 * i) + " " + std::to_string(i % 2 ? 0.01 : 0.0) + " 0\n";
    for (int i = 1; i <= n; ++i) obj += "f " + std::to_string(i) + " " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
    return obj;
}

// A grey PNG of the given size.
std::string pngBytes(int width, int height) {
    std::string file = (std::filesystem::temp_directory_path() / ("photon-limits-" + std::to_string(::getpid()) + ".png")).string();
    Image grey(width, height);
    std::fill(grey.rgb.begin(), grey.rgb.end(), 0.2f);
    writePng(grey, file, 0);
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(file);
    return bytes;
}

TEST_F(LimitsTest, RenderSizeLimitsNameTheirOption) {
    startServer({"--workers", "0", "--max-pixels", "1000", "--max-passes", "10", "--max-photons", "5000"});
    expectError(submit(smallScene()), 422, "the image's pixel count (32 x 32) is 1024, more than this server takes (1000); its "
                "administrator sets that limit with --max-pixels");
    expectError(submit(smallScene(3, 2000, 30), "?passes=11"), 422,
                "the number of passes is 11, more than this server takes (10); its administrator sets that "
                "limit with --max-passes");
    expectError(submit(smallScene(3, 6000, 30)), 422,
                "the number of photons per pass is 6000, more than this server takes (5000); its administrator "
                "sets that limit with --max-photons");
    EXPECT_EQ(submit(smallScene(10, 5000, 30))->status, 201);
}

TEST_F(LimitsTest, SceneJsonSizeIs413) {
    json scene = smallScene();
    scene["padding"] = std::string(5000, ' ');  // unknown top-level keys are not read by the loader
    const size_t size = scene.dump().size();
    startServer({"--workers", "0", "--max-scene-bytes", "4000"});
    const std::string message =
        "the scene file's size in bytes is " + std::to_string(size) +
        ", more than this server takes (4000); its administrator sets that limit with --max-scene-bytes";
    expectError(submit(scene), 413, message);
    httplib::MultipartFormDataItems items{{"scene", scene.dump(), "", "application/json"}};
    expectError(client().Post("/api/v1/jobs", items), 413, message);
    EXPECT_EQ(submit(smallScene())->status, 201);
}

TEST_F(LimitsTest, BodySizeIs413) {
    startServer({"--workers", "0", "--max-body-bytes", "1000"});
    httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "", "application/json"}};
    expectError(client().Post("/api/v1/jobs", items), 413,
                "the request body is larger than this server takes (1000 bytes); its administrator sets that "
                "limit with --max-body-bytes");
}

// Each asset part is a file staged on disk: a body of thousands of tiny parts is refused.
TEST_F(LimitsTest, UploadPartsAreCapped) {
    startServer({"--workers", "0", "--max-upload-parts", "10"});
    auto upload = [&](int assets) {
        httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "", "application/json"}};
        for (int i = 0; i < assets; ++i)
            items.push_back({"asset", "x", "extra/" + std::to_string(i) + ".txt", "text/plain"});
        return client().Post("/api/v1/jobs", items);
    };
    expectError(upload(10), 413,
                "multipart upload has more than 10 parts, the server limit (--max-upload-parts)");
    EXPECT_EQ(upload(9)->status, 201);  // the scene and nine assets: ten parts
}

TEST_F(LimitsTest, TrianglesPerSceneAreCountedOverAllMeshes) {
    json scene = smallScene();
    for (const char* file : {"a.obj", "b.obj"})
        scene["shapes"].push_back({{"type", "mesh"}, {"file", file}, {"material", "white"}});
    const int64_t base = trianglesOf(smallScene());
    const int64_t total = base + 2 * 60;
    startServer({"--workers", "0", "--max-triangles", std::to_string(total - 1)});
    httplib::MultipartFormDataItems items{{"scene", scene.dump(), "", "application/json"},
                                          {"a", objStrip(60), "a.obj", "text/plain"},
                                          {"b", objStrip(60), "b.obj", "text/plain"}};
    expectError(client().Post("/api/v1/jobs", items), 422,
                "the triangle count of all the scene's meshes is " + std::to_string(total) +
                    ", more than this server takes (" + std::to_string(total - 1) +
                    "); its administrator sets that limit with --max-triangles");
    items[2].content = objStrip(59);
    EXPECT_EQ(client().Post("/api/v1/jobs", items)->status, 201);
}

TEST_F(LimitsTest, TextureSizeIsCheckedFromTheHeader) {
    json scene = smallScene();
    scene["materials"]["white"]["albedo"] = {{"texture", "textures/t.png"}};
    startServer({"--workers", "0", "--max-texture-pixels", "4096"});
    expectError(postMultipart(scene, "textures/t.png", pngBytes(80, 60)), 422,
                "the pixel count of texture textures/t.png (80 x 60) is 4800, more than this server takes "
                "(4096); its administrator sets that limit with --max-texture-pixels");
    // An image the scene does not use is held to the limit too: it was uploaded to the job.
    expectError(postMultipart(smallScene(), "unused.png", pngBytes(65, 64)), 422,
                "the pixel count of texture unused.png (65 x 64) is 4160, more than this server takes "
                "(4096); its administrator sets that limit with --max-texture-pixels");
    EXPECT_EQ(postMultipart(scene, "textures/t.png", pngBytes(64, 64))->status, 201);
}

TEST_F(LimitsTest, ADamagedPngIsNotDecodedAndItsSceneErrorNamesIt) {
    // The chunk after IHDR declares 2 GB: libpng would reserve that much to read it.
    std::string bytes = pngBytes(8, 8);
    ASSERT_EQ(bytes.substr(12, 4), "IHDR");
    const std::string type = bytes.substr(37, 4);
    bytes.replace(33, 4, "\x7f\xff\xff\xf0");
    json scene = smallScene();
    scene["materials"]["white"]["albedo"] = {{"texture", "textures/t.png"}};
    startServer({"--workers", "0"});
    httplib::Result r = postMultipart(scene, "textures/t.png", bytes);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << r->body;
    json body = json::parse(r->body);
    EXPECT_EQ(body.value("path", ""), "materials.white.albedo.texture");
    EXPECT_EQ(body.value("error", ""), "materials.white.albedo.texture: damaged PNG: chunk " + type +
                                           " at byte 33 declares 2147483632 bytes of data, but the file has " +
                                           std::to_string(bytes.size() - 45) + " after it");
}

TEST_F(LimitsTest, StreamsOverTheLimitAre503WithRetryAfter) {
    startServer({"--workers", "0", "--max-streams", "1"});
    std::string id = submitOk(smallScene());
    std::atomic<bool> open{false};
    std::thread follower([&] {
        client().Get(("/api/v1/jobs/" + id + "/events").c_str(), [&](const char*, size_t) {
            open = true;
            return true;
        });
    });
    for (int i = 0; i < 500 && !open; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(open);
    const std::string message = "too many open streams: all 1 allowed by the server limit (--max-streams) are in use; "
                                "retry later";
    for (const std::string path : {"/events", "/stream"}) {
        httplib::Result r = client().Get(("/api/v1/jobs/" + id + path).c_str());
        expectError(r, 503, message);
        EXPECT_EQ(r->get_header_value("Retry-After"), "5");
    }
    EXPECT_EQ(client().Get("/api/v1/health")->status, 200);
    // The job ends, its stream ends, and the slot is free again.
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + id + "/cancel").c_str())->status, 200);
    follower.join();
    std::vector<SseEvent> events = followEvents(id);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back().type, "cancelled");
}

TEST_F(LimitsTest, JobsPerClientAre429) {
    startServer({"--workers", "0", "--max-jobs-per-client", "2"});
    std::string first = submitOk(smallScene());
    submitOk(smallScene());
    httplib::Result r = submit(smallScene());
    expectError(r, 429,
                "client 127.0.0.1 has 2 jobs queued or running, the server limit per client is 2 "
                "(--max-jobs-per-client); retry when one has finished");
    EXPECT_EQ(r->get_header_value("Retry-After"), "5");
    // A finished job no longer counts.
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + first + "/cancel").c_str())->status, 200);
    EXPECT_EQ(submit(smallScene())->status, 201);
}

TEST_F(LimitsTest, AFullQueueIs503) {
    startServer({"--workers", "0", "--max-queued-jobs", "2"});
    submitOk(smallScene());
    submitOk(smallScene());
    httplib::Result r = submit(smallScene());
    expectError(r, 503, "the queue is full: 2 jobs queued, the server limit is 2 (--max-queued-jobs); retry later");
    EXPECT_EQ(r->get_header_value("Retry-After"), "5");
    EXPECT_EQ(client().Get("/api/v1/jobs")->status, 200);
}

TEST_F(LimitsTest, InfoListsEveryLimitWithItsValueHere) {
    startServer({"--workers", "0", "--max-pixels", "1234", "--max-upload-parts", "7"});
    httplib::Result r = client().Get("/api/v1/info");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    json info = json::parse(r->body);
    EXPECT_EQ(info["version"], PHOTON_VERSION_FOR_TESTS);
    EXPECT_EQ(info["integrators"], json({"sppm", "path", "radiosity", "photonmap"}));
    EXPECT_EQ(info["limits"]["max_pixels"], 1234);
    EXPECT_EQ(info["limits"]["max_upload_parts"], 7);
    EXPECT_EQ(info["limits"]["max_passes"], 100000);  // a default
    EXPECT_EQ(info["limits"].size(), 19u);            // every limit photon-server --help lists
}

TEST_F(LimitsTest, OptionsAreChecked) {
    EXPECT_NE(runServerBinary({"--help"}).find("--max-jobs-per-client N"), std::string::npos);
    // --max-streams beyond what the HTTP threads allow is refused at start.
    std::string out = runServerBinary({"--max-streams", "193", "--print-routes"});
    EXPECT_EQ(out.find("GET /api/v1/health"), std::string::npos) << out;
}

}  // namespace
}  // namespace photon::test
