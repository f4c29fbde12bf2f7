// The job lifecycle over HTTP: submit, follow events, fetch images, cancel, delete.
#include <atomic>
#include <thread>
#include <photon/error_map.h>
#include <photon/image_io.h>
#include <photon/render.h>
#include "server_fixture.h"

namespace photon::test {
namespace {

class JobsTest : public ServerTest {};

TEST_F(JobsTest, SubmitFollowEventsAndFetchImages) {
    startServer();
    json scene = smallScene();
    httplib::Result r = submit(scene);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json job = json::parse(r->body);
    std::string id = job["id"];
    EXPECT_EQ(id.size(), 16u);
    EXPECT_EQ(r->get_header_value("Location"), "/api/v1/jobs/" + id);
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
    EXPECT_TRUE(job["status"] == "queued" || job["status"] == "running") << job["status"];
    EXPECT_EQ(job["settings"]["passes"], 3);
    EXPECT_EQ(job["settings"]["photons_per_pass"], 2000);
    EXPECT_EQ(job["settings"]["seed"], 7);
    EXPECT_EQ(job["settings"]["integrator"], "sppm");
    EXPECT_EQ(job["settings"]["resolution"], json::array({32, 32}));

    // Last-Event-ID 0 replays every event of the job, however late we connect.
    std::vector<SseEvent> events = followEvents(id, {{"Last-Event-ID", "0"}});
    ASSERT_FALSE(events.empty());
    std::vector<int> passes;
    for (size_t i = 0; i + 1 < events.size(); ++i) {
        EXPECT_EQ(events[i].type, "progress");
        if (events[i].data["pass"] > 0) passes.push_back(events[i].data["pass"]);
    }
    EXPECT_EQ(passes, (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(events.back().type, "done");
    EXPECT_EQ(events.back().data["status"], "completed");

    job = getJob(id);
    EXPECT_EQ(job["status"], "completed");
    EXPECT_EQ(job["pass"], 3);
    EXPECT_EQ(job["photons_traced"], 6000);
    EXPECT_TRUE(job["finished_at"].is_string());
    EXPECT_TRUE(job["error"].is_null());

    httplib::Client c = client();
    httplib::Result png = c.Get(("/api/v1/jobs/" + id + "/image").c_str());
    ASSERT_TRUE(png);
    ASSERT_EQ(png->status, 200);
    EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(png->get_header_value("X-Photon-Pass"), "3");
    EXPECT_EQ(png->get_header_value("ETag"), "\"" + id + "-3-png\"");
    Image pngImage = decodeImage(png->body, "png");
    EXPECT_EQ(pngImage.width, 32);
    EXPECT_EQ(pngImage.height, 32);

    httplib::Result exr = c.Get(("/api/v1/jobs/" + id + "/image?format=exr").c_str());
    ASSERT_TRUE(exr);
    ASSERT_EQ(exr->status, 200);
    EXPECT_EQ(exr->get_header_value("ETag"), "\"" + id + "-3-exr\"");
    Image served = decodeImage(exr->body, "exr");
    ASSERT_EQ(served.width, 32);
    ASSERT_EQ(served.height, 32);
    Image direct = renderInProcess(scene);
    ASSERT_EQ(served.rgb.size(), direct.rgb.size());
    size_t differing = 0;
    for (size_t i = 0; i < direct.rgb.size(); ++i) differing += served.rgb[i] != direct.rgb[i];
    EXPECT_EQ(differing, 0u) << "of " << direct.rgb.size() << " channel values";
}

TEST_F(JobsTest, LiveEventsStartWithTheCurrentStateThenOnePerPass) {
    startServer();
    // The long job occupies the only worker, so the small one waits in the queue while we
    // connect; cancelling the long job then lets it run under our eyes.
    std::string blocker = submitOk(longScene());
    waitForStatus(blocker, "running");
    std::string id = submitOk(smallScene());
    std::atomic<bool> connected{false};
    std::string stream;
    std::thread follower([&] {
        client().Get(("/api/v1/jobs/" + id + "/events").c_str(), [&](const char* d, size_t n) {
            stream.append(d, n);
            connected = true;
            return true;
        });
    });
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!connected && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(connected);
    client().Post(("/api/v1/jobs/" + blocker + "/cancel").c_str());
    follower.join();

    std::vector<SseEvent> events = parseSse(stream);
    ASSERT_EQ(events.size(), 5u) << stream;
    EXPECT_EQ(events[0].type, "progress");
    EXPECT_EQ(events[0].data["status"], "queued");
    EXPECT_EQ(events[0].data["pass"], 0);
    for (int pass = 1; pass <= 3; ++pass) {
        EXPECT_EQ(events[pass].type, "progress");
        EXPECT_EQ(events[pass].data["pass"], pass);
        EXPECT_EQ(events[pass].data["status"], "running");
        EXPECT_EQ(events[pass].id, std::to_string(pass));
    }
    EXPECT_EQ(events[4].type, "done");
    EXPECT_EQ(events[4].data["pass"], 3);
    // Reconnecting after the end: nothing more to send.
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + id + "/events").c_str(), {{"Last-Event-ID", "4"}})->status, 204);
}

TEST_F(JobsTest, LastEventIdResumesMidStream) {
    startServer();
    std::string id = submitOk(smallScene(5));
    waitForStatus(id, "completed");
    // A client that saw events up to id 2 (pass 2) gets the rest and nothing before.
    std::vector<SseEvent> events = followEvents(id, {{"Last-Event-ID", "2"}});
    ASSERT_EQ(events.size(), 4u);
    for (int pass = 3; pass <= 5; ++pass) {
        const SseEvent& e = events[size_t(pass - 3)];
        EXPECT_EQ(e.type, "progress");
        EXPECT_EQ(e.id, std::to_string(pass));
        EXPECT_EQ(e.data["pass"], pass);
    }
    EXPECT_EQ(events[3].type, "done");
    EXPECT_EQ(events[3].id, "6");
}

TEST_F(JobsTest, TheScenesTimeLimitEndsTheJobAfterThePassThatCrossesIt) {
    startServer();
    json scene = smallScene(100000, 20000, 16);
    scene["render"]["time_limit"] = 0.5;
    std::string id = submitOk(scene);
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed"; }, std::chrono::seconds(60));
    EXPECT_EQ(job["status"], "completed");
    EXPECT_GE(job["elapsed_seconds"].get<double>(), 0.5);
    EXPECT_GT(job["pass"].get<int>(), 0);
    EXPECT_LT(job["pass"].get<int>(), 100000);
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + id + "/image").c_str())->get_header_value("X-Photon-Pass"),
              std::to_string(job["pass"].get<int>()));
}

// By default SPPM's photons per pass follow the error (render.adaptive_photons): the job's
// photons are the engine's, pass by pass, changing only at the budget's decisions.
TEST_F(JobsTest, AdaptivePhotonCountsReachTheProgressAsTheEngineTracesThem) {
    startServer();
    json scene = smallScene(16, 50000, 16);
    scene["render"].erase("adaptive_photons");
    Renderer renderer(SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR));
    CancelToken cancel;
    std::vector<int64_t> engine;  // photons traced after each pass
    ASSERT_EQ(renderer.run(cancel, [&](const RenderProgress& p) { engine.push_back(p.photonsTraced); }),
              RenderOutcome::Completed);

    std::string id = submitOk(scene);
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed"; }, std::chrono::seconds(60));
    EXPECT_EQ(job["settings"]["photons_per_pass"], 50000);  // where the render started
    EXPECT_EQ(job["photons_traced"], engine.back());
    const json points = json::parse(client().Get(("/api/v1/jobs/" + id + "/progress").c_str())->body)["points"];
    ASSERT_EQ(points.size(), 16u);
    std::vector<int64_t> perPass;
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(points[i]["photons_traced"].get<int64_t>(), engine[i]) << "pass " << i + 1;
        perPass.push_back(engine[i] - (i ? engine[i - 1] : 0));
    }
    // Passes 1-4 at the start; decisions after passes 4 and 8, each at most a fourfold step.
    for (int i = 0; i < 4; ++i) EXPECT_EQ(perPass[i], 50000);
    for (int i = 5; i < 8; ++i) EXPECT_EQ(perPass[i], perPass[4]);
    for (int i = 9; i < 16; ++i) EXPECT_EQ(perPass[i], perPass[8]);
    EXPECT_NE(perPass[4], 50000) << "a 16 x 16 image's camera pass costs little: fewer photons pay";
    EXPECT_GE(perPass[4], 12500);
    EXPECT_GE(perPass[8] * 4, perPass[4]);
}

TEST_F(JobsTest, TheScenesTargetErrorEndsTheJobWhereTheEngineWould) {
    startServer();
    json scene = smallScene(100000, 2000, 16);
    scene["render"]["target_error"] = 0.15;
    // In process: the pass at which the estimate first reaches the target, and the estimate.
    Renderer renderer(SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR));
    CancelToken cancel;
    ASSERT_EQ(renderer.run(cancel), RenderOutcome::TargetError);
    const RenderProgress& engine = renderer.progress();

    // Submitted without it, the target given as a query parameter instead.
    json plain = scene;
    plain["render"].erase("target_error");
    std::string id = submitOk(plain, "?target_error=0.15");
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed"; }, std::chrono::seconds(60));
    EXPECT_EQ(job["settings"]["target_error"], 0.15);
    EXPECT_EQ(job["pass"], engine.pass);
    EXPECT_EQ(job["relative_error"].get<double>(), *engine.relativeError);
    EXPECT_LE(job["relative_error"].get<double>(), 0.15);
    EXPECT_EQ(job["target_error"], 0.15);
    // Each point of the history has the estimate after its pass (none after pass 1).
    httplib::Result history = client().Get(("/api/v1/jobs/" + id + "/progress").c_str());
    ASSERT_TRUE(history);
    const json points = json::parse(history->body)["points"];
    ASSERT_EQ(points.size(), size_t(engine.pass));
    EXPECT_TRUE(points[0]["relative_error"].is_null());
    EXPECT_EQ(points.back()["relative_error"].get<double>(), *engine.relativeError);
    EXPECT_GT(points[1]["relative_error"].get<double>(), 0.15);
    // The EXR carries the heat map.
    httplib::Result exr = client().Get(("/api/v1/jobs/" + id + "/image?format=exr").c_str());
    ASSERT_TRUE(exr);
    const DecodedImage layered = decodeImageBytes(exr->body, "exr");
    // ?layer=error: the heat map of that layer, as the engine draws it.
    httplib::Result map = client().Get(("/api/v1/jobs/" + id + "/image?layer=error").c_str());
    ASSERT_TRUE(map);
    ASSERT_EQ(map->status, 200) << map->body;
    EXPECT_EQ(map->get_header_value("ETag"), "\"" + id + "-" + std::to_string(engine.pass) + "-png-error\"");
    const std::vector<uint8_t> expected = encodePng(*errorHeatMap(layered.image), 0.0f);
    EXPECT_EQ(decodeImage(map->body, "png").rgb,
              decodeImage(std::string(expected.begin(), expected.end()), "png").rgb);
    // Pass 1 has no estimate; the EXR and an exposure are refused.
    httplib::Result first = client().Get(("/api/v1/jobs/" + id + "/image?layer=error&pass=1").c_str());
    ASSERT_TRUE(first);
    EXPECT_EQ(first->status, 404) << first->body;
    EXPECT_NE(first->body.find("this pass has no error estimate"), std::string::npos) << first->body;
    for (const char* query : {"?layer=error&format=exr", "?layer=error&exposure=1"}) {
        httplib::Result bad = client().Get(("/api/v1/jobs/" + id + "/image" + query).c_str());
        ASSERT_TRUE(bad);
        EXPECT_EQ(bad->status, 400) << query;
    }
    // Continued, it renders that many passes more: the target, reached, stops it no longer.
    // Eight, not fewer: on this 16 x 16 image of 2,000 photons a pass one pass's outlier can
    // lift the estimate for a few passes (pass 7's reads 1.35 with the target met at pass 4).
    httplib::Result more = client().Post(("/api/v1/jobs/" + id + "/continue?passes=8").c_str());
    ASSERT_TRUE(more);
    ASSERT_EQ(more->status, 200) << more->body;
    job = waitFor(id, [](const json& j) { return j["status"] == "completed" && j["pass"] > 0; }, std::chrono::seconds(60));
    job = waitFor(id, [&](const json& j) { return j["status"] == "completed" && j["pass"] == engine.pass + 8; },
                  std::chrono::seconds(60));
    EXPECT_EQ(job["settings"]["passes"], engine.pass + 8);
    EXPECT_TRUE(job["target_error"].is_null());
    EXPECT_LT(job["relative_error"].get<double>(), *engine.relativeError);
}

TEST_F(JobsTest, QueryParametersOverrideTheRenderBlock) {
    startServer({"--workers", "0"});
    httplib::Result r = submit(smallScene(), "?passes=5&photons_per_pass=1000&seed=42&priority=3");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json job = json::parse(r->body);
    EXPECT_EQ(job["settings"]["passes"], 5);
    EXPECT_EQ(job["settings"]["photons_per_pass"], 1000);
    EXPECT_EQ(job["settings"]["seed"], 42);
    EXPECT_EQ(job["priority"], 3);
    EXPECT_EQ(job["status"], "queued");
}

TEST_F(JobsTest, ListsNewestFirstWithFilterAndPaging) {
    startServer({"--workers", "0"});
    std::string a = submitOk(smallScene()), b = submitOk(smallScene()), c = submitOk(smallScene());
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + b + "/cancel").c_str())->status, 200);
    json all = json::parse(client().Get("/api/v1/jobs")->body);
    EXPECT_EQ(all["total"], 3);
    ASSERT_EQ(all["jobs"].size(), 3u);
    EXPECT_EQ(all["jobs"][0]["id"], c);
    EXPECT_EQ(all["jobs"][1]["id"], b);
    EXPECT_EQ(all["jobs"][2]["id"], a);
    json queued = json::parse(client().Get("/api/v1/jobs?status=queued&limit=1&offset=1")->body);
    EXPECT_EQ(queued["total"], 2);
    ASSERT_EQ(queued["jobs"].size(), 1u);
    EXPECT_EQ(queued["jobs"][0]["id"], a);
    EXPECT_EQ(client().Get("/api/v1/jobs?status=bogus")->status, 400);
    EXPECT_EQ(client().Get("/api/v1/jobs?limit=0")->status, 400);
}

TEST_F(JobsTest, ImageRevalidationAndNoImageBeforeFirstPass) {
    startServer({"--workers", "0"});  // nothing renders: the job stays queued
    std::string queued = submitOk(smallScene());
    httplib::Result none = client().Get(("/api/v1/jobs/" + queued + "/image").c_str());
    ASSERT_TRUE(none);
    EXPECT_EQ(none->status, 404);
    EXPECT_TRUE(json::parse(none->body).contains("error"));
    stopServer();

    startServer();  // the same data directory: the queued job now runs
    waitForStatus(queued, "completed");
    httplib::Client c = client();
    std::string path = "/api/v1/jobs/" + queued + "/image";
    httplib::Result first = c.Get(path.c_str());
    ASSERT_TRUE(first);
    ASSERT_EQ(first->status, 200);
    std::string etag = first->get_header_value("ETag");
    EXPECT_EQ(etag, "\"" + queued + "-3-png\"");
    httplib::Result again = c.Get(path.c_str(), {{"If-None-Match", etag}});
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 304);
    EXPECT_TRUE(again->body.empty());
    httplib::Result other = c.Get(path.c_str(), {{"If-None-Match", "\"" + queued + "-2-png\""}});
    EXPECT_EQ(other->status, 200);
    EXPECT_EQ(c.Get((path + "?format=tiff").c_str())->status, 400);
}

TEST_F(JobsTest, CancelRunningJobKeepsItsImage) {
    startServer();
    std::string id = submitOk(longScene());
    json running = waitFor(id, [](const json& j) { return j["pass"] >= 1; });
    ASSERT_EQ(running["status"], "running");

    EXPECT_EQ(client().Delete(("/api/v1/jobs/" + id).c_str())->status, 409);  // not finished

    auto start = std::chrono::steady_clock::now();
    httplib::Result r = client().Post(("/api/v1/jobs/" + id + "/cancel").c_str());
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->status == 202 || r->status == 200) << r->status;
    json job = waitForStatus(id, "cancelled");
    EXPECT_EQ(job["status"], "cancelled");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    int pass = job["pass"];
    EXPECT_GE(pass, 1);
    EXPECT_LT(pass, 50000);

    httplib::Result image = client().Get(("/api/v1/jobs/" + id + "/image").c_str());
    ASSERT_TRUE(image);
    EXPECT_EQ(image->status, 200);
    EXPECT_EQ(image->get_header_value("X-Photon-Pass"), std::to_string(pass));
    EXPECT_EQ(decodeImage(image->body, "png").width, 48);

    // The event stream of a finished job is its final event.
    std::vector<SseEvent> events = followEvents(id);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].type, "cancelled");

    EXPECT_EQ(client().Post(("/api/v1/jobs/" + id + "/cancel").c_str())->status, 409);
    EXPECT_EQ(client().Delete(("/api/v1/jobs/" + id).c_str())->status, 204);
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + id).c_str())->status, 404);
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + id + "/image").c_str())->status, 404);
    EXPECT_FALSE(std::filesystem::exists(dataDir() / "jobs" / id));
}

TEST_F(JobsTest, CancelQueuedJobAtOnceAndEventsReportIt) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    std::vector<SseEvent> events;
    std::thread follower([&] { events = followEvents(id); });
    // The first event (current state) arrives before the cancel in most runs; either way
    // the stream must end with the cancelled event.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    httplib::Result r = client().Post(("/api/v1/jobs/" + id + "/cancel").c_str());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_EQ(json::parse(r->body)["status"], "cancelled");
    follower.join();
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back().type, "cancelled");
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + id + "/image").c_str())->status, 404);
}

TEST_F(JobsTest, StreamSendsPngFramesUntilTheJobEnds) {
    startServer();
    std::string id = submitOk(smallScene(4));
    waitForStatus(id, "completed");
    std::string body;
    httplib::Result r = client().Get(("/api/v1/jobs/" + id + "/stream").c_str(), [&](const char* d, size_t n) {
        body.append(d, n);
        return true;
    });
    ASSERT_TRUE(r);
    EXPECT_EQ(r->get_header_value("Content-Type"), "multipart/x-mixed-replace; boundary=frame");
    EXPECT_NE(body.find("--frame\r\nContent-Type: image/png\r\n"), std::string::npos);
    EXPECT_NE(body.find("X-Photon-Pass: 4\r\n"), std::string::npos);
    EXPECT_EQ(body.substr(body.size() - 11), "--frame--\r\n");
}

TEST_F(JobsTest, HealthMetricsAndHomePage) {
    startServer();
    httplib::Result health = client().Get("/api/v1/health");
    ASSERT_TRUE(health);
    EXPECT_EQ(health->status, 200);
    EXPECT_EQ(json::parse(health->body), json({{"status", "ok"}}));
    std::string id = submitOk(smallScene());
    waitForStatus(id, "completed");
    std::string metrics = client().Get("/metrics")->body;
    EXPECT_NE(metrics.find("photon_jobs{status=\"completed\"} 1\n"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("photon_passes_total 3\n"), std::string::npos);
    EXPECT_NE(metrics.find("photon_photons_traced_total 6000\n"), std::string::npos);
    EXPECT_NE(metrics.find("photon_render_seconds_total "), std::string::npos);
    EXPECT_NE(metrics.find("photon_http_requests_total{route=\"/api/v1/jobs\",code=\"201\"} 1\n"), std::string::npos);
    EXPECT_NE(metrics.find("photon_http_requests_total{route=\"/api/v1/health\",code=\"200\"} 1\n"), std::string::npos);
    httplib::Result home = client().Get("/");
    ASSERT_TRUE(home);
    EXPECT_EQ(home->status, 200);
    EXPECT_NE(home->get_header_value("Content-Type").find("text/html"), std::string::npos);
    EXPECT_NE(home->body.find("photon render service"), std::string::npos);
}

// Each method's record carries its own figures, as the engine reports them in process:
// samples per pixel for those that take one camera sample a pixel a pass, the radiosity
// solve, the photon maps' sizes; SPPM's are the record's photons and radius.
TEST_F(JobsTest, EachMethodReportsItsOwnFigures) {
    startServer();
    auto firstPass = [](const json& scene) {
        Renderer renderer(SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR));
        CancelToken never;
        EXPECT_TRUE(renderer.renderPass(never));
        return renderer.progress().lastPass;
    };
    for (const char* integrator : {"sppm", "path", "radiosity", "photonmap"}) {
        json scene = smallScene(2, 3000, 16);
        scene["render"]["integrator"] = integrator;
        scene["render"]["photonmap"] = {{"global_photons", 3000}, {"caustic_photons", 2000}};
        if (std::string(integrator) != "photonmap") scene["render"].erase("photonmap");
        // Radiosity's first pass solves the whole scene: under ThreadSanitizer on a busy
        // machine that took over the fixture's default 20 s.
        const json job = waitFor(submitOk(scene), [](const json& j) { return j["status"] == "completed"; },
                                 std::chrono::seconds(180));
        ASSERT_EQ(job["status"], "completed") << integrator;
        const PassStats stats = firstPass(scene);
        json expected = json::object();
        if (std::string(integrator) != "sppm") expected["samples_per_pixel"] = 2;
        if (std::string(integrator) == "radiosity") {
            ASSERT_GT(stats.patches, 0);
            expected["patches"] = stats.patches;
            expected["solver_iterations"] = stats.solverIterations;
            expected["solver_residual"] = stats.solverResidual;
        }
        if (std::string(integrator) == "photonmap") {
            ASSERT_GT(stats.globalMapPhotons, 0);
            expected["global_map_photons"] = stats.globalMapPhotons;
            expected["caustic_map_photons"] = stats.causticMapPhotons;
        }
        EXPECT_EQ(job["figures"], expected) << integrator;
    }
}

}  // namespace
}  // namespace photon::test
