// Uploaded assets stay inside their job's folder: unsafe names are refused naming the part,
// files are created without following symlinks or replacing anything, and a scene path that
// resolves through a symlink planted in the data directory is refused when the job runs.
#include <fstream>
#include "server/errors.h"
#include "server/staged_upload.h"
#include "server_fixture.h"

namespace photon::test {
namespace {

namespace fs = std::filesystem;

class AssetsTest : public ServerTest {
protected:
    httplib::Result upload(const std::string& name, const std::string& part = "asset") {
        httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "", "application/json"},
                                              {part, "v 0 0 0\n", name, "text/plain"}};
        return client().Post("/api/v1/jobs", items);
    }
};

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

TEST_F(AssetsTest, UnsafeNamesAre400NamingThePart) {
    startServer({"--workers", "0"});
    const std::string deep = repeat("d/", 16) + "x.obj";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"a/../../x.obj", "asset name must not contain \"..\""},
        {"../x.obj", "asset name must not contain \"..\""},
        {"/etc/x.obj", "asset name must be a relative path"},
        {"C:/x.obj", "asset name must not start with a drive letter"},
        {"c:x.obj", "asset name must not start with a drive letter"},
        {"meshes\\x.obj", "asset name contains a backslash"},
        {"a\tb.obj", "asset name contains a control character"},
        {"a\x7f.obj", "asset name contains a control character"},
        {repeat("n", 513), "asset name is 513 bytes, longer than 512"},
        {repeat("n", 256) + "/x.obj", "asset name has a component longer than 255 bytes"},
        {deep, "asset name has 17 path components, more than 16"},
        {"scene.json", "asset name \"scene.json\" is reserved"},
        {"./image.png", "asset name \"image.png\" is reserved"},
    };
    for (const auto& [name, problem] : cases) {
        httplib::Result r = upload(name, "mesh-part");
        ASSERT_TRUE(r) << name;
        EXPECT_EQ(r->status, 400) << name;
        EXPECT_EQ(json::parse(r->body).value("error", ""),
                  problem + ": part \"mesh-part\" (file name \"" + name + "\")");
    }
    EXPECT_TRUE(fs::is_empty(dataDir() / "jobs"));
    EXPECT_TRUE(fs::is_empty(dataDir() / "tmp"));
    // At the limits themselves names are fine.
    EXPECT_EQ(upload(repeat("d/", 15) + repeat("n", 255))->status, 201);
}

// Files the scene does not name are not kept (they would only take the client's disk); the
// job's warnings name each, and what is kept counts toward the client's bytes.
TEST_F(AssetsTest, AssetsTheSceneDoesNotNameAreNotStored) {
    startServer({"--workers", "0"});
    json scene = smallScene();
    scene["shapes"].push_back({{"type", "mesh"}, {"file", "meshes/tri.obj"}, {"material", scene["shapes"][0]["material"]}});
    httplib::MultipartFormDataItems items{{"scene", scene.dump(), "", "application/json"},
                                          {"mesh", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "meshes/tri.obj", "text/plain"},
                                          {"notes", "not a scene file", "notes/readme.txt", "text/plain"},
                                          {"extra", "v 0 0 0\n", "unused.obj", "text/plain"}};
    httplib::Result r = client().Post("/api/v1/jobs", items);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json job = json::parse(r->body);
    EXPECT_EQ(job["warnings"], json({"asset \"notes/readme.txt\" is not used by the scene and was not stored",
                                     "asset \"unused.obj\" is not used by the scene and was not stored"}));
    const fs::path folder = dataDir() / "jobs" / job["id"].get<std::string>();
    EXPECT_TRUE(fs::is_regular_file(folder / "meshes" / "tri.obj"));
    EXPECT_FALSE(fs::exists(folder / "unused.obj"));
    EXPECT_FALSE(fs::exists(folder / "notes" / "readme.txt"));
    EXPECT_EQ(getJob(job["id"])["warnings"], job["warnings"]);  // kept with the job
    EXPECT_EQ(json::parse(submit(smallScene())->body)["warnings"], json::array());
}

TEST_F(AssetsTest, OneClientsBytesAreBounded) {
    const std::string scene = smallScene().dump();
    const int64_t bytes = int64_t(scene.size());
    startServer({"--workers", "0", "--max-client-bytes", std::to_string(2 * bytes - 1)});
    EXPECT_EQ(submit(smallScene())->status, 201);
    httplib::Result second = submit(smallScene());
    ASSERT_TRUE(second);
    EXPECT_EQ(second->status, 429);
    EXPECT_EQ(second->get_header_value("Retry-After"), "5");
    EXPECT_EQ(json::parse(second->body)["error"],
              "client 127.0.0.1 has " + std::to_string(bytes) +
                  " bytes of scenes and assets in jobs queued or running; with this job's " + std::to_string(bytes) +
                  " that exceeds the server limit per client of " + std::to_string(2 * bytes - 1) +
                  " (--max-client-bytes); retry when one has finished");
    // A finished job's bytes no longer count.
    std::string first = json::parse(client().Get("/api/v1/jobs")->body)["jobs"][0]["id"];
    ASSERT_EQ(client().Post("/api/v1/jobs/" + first + "/cancel")->status, 200);
    EXPECT_EQ(submit(smallScene())->status, 201);
}

// The staging folder is fresh, so these are planted by hand: creation must neither follow
// a symlink nor replace a file, wherever on the path it sits.
class StagedUploadTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("photon-staged-" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_ / "staging");
        fs::create_directories(root_ / "outside");
    }
    void TearDown() override { fs::remove_all(root_); }
    // The BadRequest message beginAsset throws, or "" if it succeeds.
    std::string refusal(const std::string& name) {
        server::StagedUpload upload(root_ / "staging", 1000);
        try {
            upload.beginAsset("asset", name);
            upload.appendAsset("data", 4);
            upload.endAsset();
            upload.markCommitted();
        } catch (const server::ServiceError& e) {
            EXPECT_EQ(e.kind(), server::ErrorKind::BadRequest);
            upload.markCommitted();  // keep the planted files for the checks
            return e.what();
        }
        return "";
    }
    fs::path root_;
};

TEST_F(StagedUploadTest, NoWriteThroughSymlinksOrOverFiles) {
    fs::create_directory_symlink(root_ / "outside", root_ / "staging" / "meshes");
    EXPECT_EQ(refusal("meshes/x.obj"), "asset meshes/x.obj: a folder on its path is a symlink or a file");
    EXPECT_EQ(refusal("meshes/deeper/x.obj"), "asset meshes/deeper/x.obj: a folder on its path is a symlink or a file");
    {
        std::ofstream(root_ / "outside" / "target.obj") << "original";
    }
    fs::create_symlink(root_ / "outside" / "target.obj", root_ / "staging" / "x.obj");
    EXPECT_EQ(refusal("x.obj"), "asset x.obj: a file or symlink of that name already exists");
    std::ofstream(root_ / "staging" / "plain") << "a file";
    EXPECT_EQ(refusal("plain/x.obj"), "asset plain/x.obj: a folder on its path is a symlink or a file");
    EXPECT_EQ(refusal("plain"), "asset plain: a file or symlink of that name already exists");
    // Nothing reached the outside folder, and the file there is unchanged.
    EXPECT_EQ(std::distance(fs::directory_iterator(root_ / "outside"), fs::directory_iterator()), 1);
    std::ifstream target(root_ / "outside" / "target.obj");
    std::string text;
    target >> text;
    EXPECT_EQ(text, "original");
    // Ordinary nested names create their folders.
    EXPECT_EQ(refusal("new/folder/x.obj"), "");
    EXPECT_EQ(fs::file_size(root_ / "staging" / "new" / "folder" / "x.obj"), 4u);
}

TEST_F(AssetsTest, AScenePathThroughASymlinkInTheDataDirectoryFailsTheJob) {
    startServer({"--workers", "0"});
    json scene = smallScene(2);
    scene["shapes"].push_back({{"type", "mesh"}, {"file", "meshes/tri.obj"}, {"material", "white"}});
    const std::string obj = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf 1 2 3\n";
    httplib::MultipartFormDataItems items{{"scene", scene.dump(), "", "application/json"},
                                          {"asset", obj, "meshes/tri.obj", "text/plain"}};
    httplib::Result r = client().Post("/api/v1/jobs", items);
    ASSERT_EQ(r->status, 201) << r->body;
    std::string id = json::parse(r->body)["id"];
    ASSERT_EQ(stopServer(), 0);
    // Someone replaces the mesh with a symlink to a file outside the job's folder.
    fs::path outside = dataDir() / "outside.obj";
    std::ofstream(outside) << obj;
    fs::path mesh = dataDir() / "jobs" / id / "meshes" / "tri.obj";
    fs::remove(mesh);
    fs::create_symlink(outside, mesh);
    startServer({"--workers", "1"});
    json job = waitFor(id, [](const json& j) { return j["status"] == "failed" || j["status"] == "completed"; });
    EXPECT_EQ(job["status"], "failed");
    EXPECT_EQ(job["error"], "shapes[8].file: must be a relative path inside the scene folder");
    EXPECT_EQ(client().Get("/api/v1/health")->status, 200);
}

}  // namespace
}  // namespace photon::test
