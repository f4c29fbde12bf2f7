// Every client error maps to its status code with an RFC 9457 problem body, and none harms
// the server.
#include <unistd.h>
#include <fstream>
#include "server_fixture.h"

namespace photon::test {
namespace {

class ErrorsTest : public ServerTest {};

json errorBody(const httplib::Result& r) { return problemOf(r); }

TEST_F(ErrorsTest, MalformedJsonIs400) {
    startServer({"--workers", "0"});
    httplib::Result r = client().Post("/api/v1/jobs", "{\"camera\": [1, 2", "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400);
    json body = errorBody(r);
    EXPECT_NE(body["error"].get<std::string>().find("malformed JSON"), std::string::npos) << body;
    EXPECT_EQ(body["path"], "");
    EXPECT_EQ(client().Post("/api/v1/jobs", "", "application/json")->status, 400);
    EXPECT_EQ(client().Post("/api/v1/jobs", "[1, 2]", "application/json")->status, 400);
}

TEST_F(ErrorsTest, SceneErrorIs400WithItsJsonPath) {
    startServer({"--workers", "0"});
    json scene = smallScene();
    scene["shapes"].push_back({{"type", "sphere"}, {"center", {0, 1, 0}}, {"radius", -0.5}, {"material", "white"}});
    httplib::Result r = submit(scene);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400);
    json body = errorBody(r);
    EXPECT_EQ(body["type"], "urn:photon:problem:scene-invalid");
    EXPECT_EQ(body["title"], "Invalid scene");
    EXPECT_EQ(body["path"], "shapes[8].radius");
    EXPECT_EQ(body["pointer"], "/shapes/8/radius");
    // A rejected upload leaves nothing behind.
    EXPECT_TRUE(std::filesystem::is_empty(dataDir() / "jobs"));
    EXPECT_TRUE(std::filesystem::is_empty(dataDir() / "tmp"));
}

TEST_F(ErrorsTest, BadQueryParametersAre400) {
    startServer({"--workers", "0"});
    EXPECT_EQ(submit(smallScene(), "?passes=abc")->status, 400);
    EXPECT_EQ(submit(smallScene(), "?passes=0")->status, 400);
    EXPECT_EQ(submit(smallScene(), "?seed=-1")->status, 400);
    EXPECT_EQ(submit(smallScene(), "?priority=1.5")->status, 400);
}

TEST_F(ErrorsTest, UnknownJobsAndRoutesAre404) {
    startServer({"--workers", "0"});
    httplib::Client c = client();
    for (std::string path : {"/api/v1/jobs/0123456789abcdef", "/api/v1/jobs/0123456789abcdef/image",
                             "/api/v1/jobs/0123456789abcdef/events", "/api/v1/jobs/0123456789abcdef/stream",
                             "/api/v1/nothing-here"}) {
        httplib::Result r = c.Get(path.c_str());
        ASSERT_TRUE(r) << path;
        EXPECT_EQ(r->status, 404) << path;
        EXPECT_EQ(errorBody(r)["type"], path == "/api/v1/nothing-here" ? "about:blank" : "urn:photon:problem:not-found");
    }
    EXPECT_EQ(c.Post("/api/v1/jobs/0123456789abcdef/cancel")->status, 404);
    EXPECT_EQ(c.Delete("/api/v1/jobs/0123456789abcdef")->status, 404);
}

// A job that exists but has no image yet is told apart from no job at all, and says when to
// look again.
TEST_F(ErrorsTest, NoImageYetIsItsOwnProblemWithRetryAfter) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    httplib::Result r = client().Get(("/api/v1/jobs/" + id + "/image").c_str());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 404);
    EXPECT_EQ(r->get_header_value("Retry-After"), "5");
    json problem = errorBody(r);
    EXPECT_EQ(problem["type"], "urn:photon:problem:not-ready");
    EXPECT_EQ(problem["title"], "Not ready yet");
    EXPECT_EQ(problem["detail"], "job " + id + " has no image yet");
}

TEST_F(ErrorsTest, WrongStateIs409) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    httplib::Result del = client().Delete(("/api/v1/jobs/" + id).c_str());
    EXPECT_EQ(del->status, 409);
    errorBody(del);
    EXPECT_EQ(client().Post(("/api/v1/jobs/" + id + "/cancel").c_str())->status, 200);
    EXPECT_EQ(client().Post(("/api/v1/jobs/" + id + "/cancel").c_str())->status, 409);
}

TEST_F(ErrorsTest, OversizedBodyIs413) {
    startServer({"--workers", "0", "--max-body-bytes", "1000"});
    json scene = smallScene();
    ASSERT_GT(scene.dump().size(), 1000u);
    httplib::Result r = submit(scene);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 413);
    errorBody(r);
    // The server is still fine.
    EXPECT_EQ(client().Get("/api/v1/health")->status, 200);
}

TEST_F(ErrorsTest, LimitsAre422) {
    startServer({"--workers", "0", "--max-pixels", "1000", "--max-passes", "10", "--max-photons", "5000"});
    httplib::Result pixels = submit(smallScene());  // 32x32 = 1024 pixels
    ASSERT_TRUE(pixels);
    EXPECT_EQ(pixels->status, 422);
    errorBody(pixels);
    EXPECT_EQ(submit(smallScene(3, 2000, 30))->status, 201);
    EXPECT_EQ(submit(smallScene(3, 2000, 30), "?passes=11")->status, 422);
    EXPECT_EQ(submit(smallScene(3, 2000, 30), "?photons_per_pass=5001")->status, 422);
}

TEST_F(ErrorsTest, TokenIsRequiredExceptForHealthAndThePage) {
    startServer({"--workers", "0", "--token", "s3cret-token"});
    httplib::Client c = client();  // no token yet
    httplib::Result none = c.Get("/api/v1/jobs");
    ASSERT_TRUE(none);
    EXPECT_EQ(none->status, 401);
    errorBody(none);
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Authorization", "Bearer wrong"}})->status, 401);
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Authorization", "Bearer s3cret-token-and-more"}})->status, 401);
    EXPECT_EQ(c.Get("/metrics")->status, 401);
    EXPECT_EQ(submit(smallScene())->status, 401);
    EXPECT_EQ(c.Get("/api/v1/health")->status, 200);
    // The page itself loads without the token (it asks for it before calling the API).
    httplib::Result page = c.Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("<html"), std::string::npos);
    EXPECT_EQ(c.Get("/app.js")->status, 404);  // unknown static files are plain 404s
    setToken("s3cret-token");
    EXPECT_EQ(client().Get("/api/v1/jobs")->status, 200);
    EXPECT_EQ(submit(smallScene())->status, 201);
}

// The page trades its token for a session cookie, which then authorises what a browser
// fetches by itself: an EventSource stream above all.
TEST_F(ErrorsTest, ASessionCookieStandsInForTheToken) {
    startServer({"--workers", "0", "--token", "s3cret-token"});
    httplib::Client c = client();
    EXPECT_EQ(c.Post("/api/v1/session")->status, 401);
    httplib::Result started = c.Post("/api/v1/session", {{"Authorization", "Bearer s3cret-token"}}, "", "application/json");
    ASSERT_TRUE(started);
    EXPECT_EQ(started->status, 204);
    const std::string cookie = started->get_header_value("Set-Cookie");
    ASSERT_EQ(cookie.rfind("photon_session=", 0), 0u) << cookie;
    const std::string id = cookie.substr(15, cookie.find(';') - 15);
    EXPECT_EQ(id.size(), 64u);
    EXPECT_EQ(cookie.substr(cookie.find(';')), "; Path=/; Max-Age=86400; HttpOnly; SameSite=Strict");
    httplib::Headers withCookie{{"Cookie", "theme=dark; photon_session=" + id}};
    EXPECT_EQ(c.Get("/api/v1/jobs", withCookie)->status, 200);
    EXPECT_EQ(c.Post("/api/v1/jobs", withCookie, smallScene().dump(), "application/json")->status, 201);
    EXPECT_EQ(c.Get("/api/v1/jobs", {{"Cookie", "photon_session=" + std::string(64, '0')}})->status, 401);
    // Ending it: the cookie is cleared and the id refused from then on.
    httplib::Result ended = c.Delete("/api/v1/session", withCookie);
    ASSERT_TRUE(ended);
    EXPECT_EQ(ended->status, 204);
    EXPECT_EQ(ended->get_header_value("Set-Cookie"), "photon_session=; Path=/; Max-Age=0; HttpOnly; SameSite=Strict");
    EXPECT_EQ(c.Get("/api/v1/jobs", withCookie)->status, 401);
}

TEST_F(ErrorsTest, WithoutATokenASessionSetsNoCookie) {
    startServer({"--workers", "0"});
    httplib::Result started = client().Post("/api/v1/session");
    ASSERT_TRUE(started);
    EXPECT_EQ(started->status, 204);
    EXPECT_FALSE(started->has_header("Set-Cookie"));
}

TEST_F(ErrorsTest, AKnownRouteWithAnotherMethodIs405WithAllow) {
    startServer({"--workers", "0"});
    httplib::Client c = client();
    httplib::Result health = c.Delete("/api/v1/health");
    ASSERT_TRUE(health);
    EXPECT_EQ(health->status, 405);
    EXPECT_EQ(health->get_header_value("Allow"), "GET");
    EXPECT_EQ(errorBody(health)["error"], "DELETE is not one of this route's methods: GET");
    httplib::Result job = c.Put("/api/v1/jobs/0123456789abcdef", "{}", "application/json");
    EXPECT_EQ(job->status, 405);
    EXPECT_EQ(job->get_header_value("Allow"), "GET, DELETE, PATCH");
    httplib::Result cancel = c.Get("/api/v1/jobs/0123456789abcdef/cancel");
    EXPECT_EQ(cancel->status, 405);
    EXPECT_EQ(cancel->get_header_value("Allow"), "POST");
    EXPECT_EQ(c.Delete("/api/v1/nothing-here")->status, 404);
}

// A token on the command line shows in ps; a file or the environment keeps it out of sight.
TEST_F(ErrorsTest, TheTokenCanComeFromAFileOrTheEnvironment) {
    const std::filesystem::path file = dataDir().parent_path() / ("photon-token-" + std::to_string(::getpid()));
    std::ofstream(file) << "from-a-file\n";
    startServer({"--workers", "0", "--token-file", file.string()});
    EXPECT_EQ(client().Get("/api/v1/jobs")->status, 401);
    setToken("from-a-file");
    EXPECT_EQ(client().Get("/api/v1/jobs")->status, 200);
    stopServer();
    std::filesystem::remove(file);

    ::setenv("PHOTON_TOKEN", "from-the-environment", 1);
    startServer({"--workers", "0"});
    ::unsetenv("PHOTON_TOKEN");
    EXPECT_EQ(client().Get("/api/v1/jobs")->status, 401);  // the file's token no longer counts
    setToken("from-the-environment");
    EXPECT_EQ(client().Get("/api/v1/jobs")->status, 200);

    std::string both = runServerBinary({"--token", "a", "--token-file", "/dev/null"});
    EXPECT_NE(both.find("--token excludes --token-file"), std::string::npos) << both;
    std::string empty = runServerBinary({"--token-file", "/dev/null"});
    EXPECT_NE(empty.find("--token-file /dev/null: cannot read a line"), std::string::npos) << empty;
}

TEST_F(ErrorsTest, MultipartAssetsMustStayInsideTheJobFolder) {
    startServer({"--workers", "0"});
    json scene = smallScene();
    std::filesystem::path outside = dataDir().parent_path() / "evil.obj";
    std::filesystem::remove(outside);
    const std::vector<std::string> names{"../evil.obj",      "meshes/../../evil.obj", "/tmp/evil.obj",
                                         "meshes\\evil.obj", std::string("a\0b.obj", 7),  "scene.json"};
    for (const std::string& name : names) {
        httplib::MultipartFormDataItems items{
            {"scene", scene.dump(), "scene.json", "application/json"},
            {"asset", "v 0 0 0\n", name, "text/plain"},
        };
        httplib::Result r = client().Post("/api/v1/jobs", items);
        ASSERT_TRUE(r) << name;
        EXPECT_EQ(r->status, 400) << name << ": " << r->body;
        errorBody(r);
    }
    EXPECT_FALSE(std::filesystem::exists(outside));
    EXPECT_FALSE(std::filesystem::exists(dataDir() / "evil.obj"));
    EXPECT_TRUE(std::filesystem::is_empty(dataDir() / "jobs"));
    EXPECT_TRUE(std::filesystem::is_empty(dataDir() / "tmp"));
}

TEST_F(ErrorsTest, MultipartWithAssetsIsAccepted) {
    startServer({"--workers", "0", "--max-asset-bytes", "100000"});
    json scene = smallScene();
    scene["shapes"].push_back({{"type", "mesh"}, {"file", "meshes/tri.obj"}, {"material", "white"}});
    std::string obj = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf 1 2 3\n";
    httplib::MultipartFormDataItems items{
        {"scene", scene.dump(), "", "application/json"},
        {"asset", obj, "meshes/tri.obj", "text/plain"},
    };
    httplib::Result r = client().Post("/api/v1/jobs", items);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    std::string id = json::parse(r->body)["id"];
    EXPECT_TRUE(std::filesystem::exists(dataDir() / "jobs" / id / "meshes" / "tri.obj"));
    EXPECT_TRUE(std::filesystem::exists(dataDir() / "jobs" / id / "scene.json"));

    // The scene names an asset the upload lacks: a scene error with the path.
    httplib::MultipartFormDataItems missing{{"scene", scene.dump(), "", "application/json"}};
    httplib::Result m = client().Post("/api/v1/jobs", missing);
    EXPECT_EQ(m->status, 400);
    EXPECT_EQ(errorBody(m)["path"], "shapes[8].file");

    // An asset over --max-asset-bytes.
    httplib::MultipartFormDataItems big{
        {"scene", scene.dump(), "", "application/json"},
        {"asset", std::string(200000, 'x'), "meshes/tri.obj", "text/plain"},
    };
    EXPECT_EQ(client().Post("/api/v1/jobs", big)->status, 422);

    httplib::MultipartFormDataItems noScene{{"asset", obj, "meshes/tri.obj", "text/plain"}};
    EXPECT_EQ(client().Post("/api/v1/jobs", noScene)->status, 400);
}

}  // namespace
}  // namespace photon::test
