// What can be done to a job after submission: its priority changed while it waits, a copy
// with other settings, its scene read back as it was sent.
#include <cstdio>
#include <sstream>
#include <thread>
#include "server_fixture.h"

namespace photon::test {
namespace {

namespace fs = std::filesystem;

class ActionsTest : public ServerTest {
protected:
    httplib::Result patch(const std::string& id, const std::string& body) {
        return client().Patch(("/api/v1/jobs/" + id).c_str(), body, "application/json");
    }
};

TEST_F(ActionsTest, APriorityRaisedWhileQueuedRunsTheJobFirst) {
    startServer({"--workers", "1"});
    std::string blocking = submitOk(longScene());
    waitForStatus(blocking, "running");
    std::string first = submitOk(smallScene());
    std::string second = submitOk(smallScene());
    httplib::Result raised = patch(second, R"({"priority": 5})");
    ASSERT_TRUE(raised);
    ASSERT_EQ(raised->status, 200) << raised->body;
    json job = json::parse(raised->body);
    EXPECT_EQ(job["priority"], 5);
    EXPECT_GE(job["updated_at"].get<std::string>(), job["created_at"].get<std::string>());
    EXPECT_EQ(getJob(second)["priority"], 5);
    // Once the worker is free, the raised job goes first though it was submitted later.
    ASSERT_EQ(client().Post("/api/v1/jobs/" + blocking + "/cancel")->status, 202);
    json secondDone = waitForStatus(second, "completed");
    json firstDone = waitForStatus(first, "completed");
    EXPECT_GE(firstDone["started_at"].get<std::string>(), secondDone["finished_at"].get<std::string>());
    // A job that has started keeps its priority.
    httplib::Result late = patch(second, R"({"priority": 1})");
    EXPECT_EQ(late->status, 409);
    EXPECT_EQ(problemOf(late)["detail"], "job " + second + " is completed: its priority can change only while it is queued");
}

TEST_F(ActionsTest, OnlyThePriorityCanBeChanged) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    auto refused = [&](const std::string& body) {
        httplib::Result r = patch(id, body);
        EXPECT_EQ(r->status, 400) << body;
        return problemOf(r)["detail"].get<std::string>();
    };
    EXPECT_EQ(refused(R"({"priority": 1, "passes": 9})"), "\"passes\" cannot be changed; only \"priority\" can");
    EXPECT_EQ(refused(R"({"priority": 1.5})"), "priority: must be a 32-bit integer");
    EXPECT_EQ(refused(R"({"priority": 3000000000})"), "priority: must be a 32-bit integer");
    EXPECT_EQ(refused("{}"), "nothing to change: give {\"priority\": N}");
    EXPECT_EQ(refused("[1]"), "the body must be a JSON object such as {\"priority\": 5}");
    EXPECT_EQ(patch("0123456789abcdef", R"({"priority": 1})")->status, 404);
    EXPECT_EQ(getJob(id)["priority"], 0);
}

TEST_F(ActionsTest, ACloneHasTheSceneAndAssetsWithNewSettings) {
    startServer({"--workers", "0"});
    json scene = smallScene(3, 2000);
    scene["shapes"].push_back({{"type", "mesh"}, {"file", "meshes/tri.obj"}, {"material", scene["shapes"][0]["material"]}});
    const std::string sceneText = scene.dump(2);
    httplib::MultipartFormDataItems items{{"scene", sceneText, "atrium.json", "application/json"},
                                          {"mesh", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "meshes/tri.obj", "text/plain"},
                                          {"label", "draft", "", ""}};
    json original = json::parse(client().Post("/api/v1/jobs", items)->body);
    const std::string id = original["id"];
    httplib::Result r = client().Post(("/api/v1/jobs/" + id + "/clone?passes=7&seed=99").c_str());
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    json copy = json::parse(r->body);
    EXPECT_NE(copy["id"], id);
    EXPECT_EQ(r->get_header_value("Location"), "/api/v1/jobs/" + copy["id"].get<std::string>());
    EXPECT_EQ(copy["settings"]["passes"], 7);
    EXPECT_EQ(copy["settings"]["seed"], 99);
    EXPECT_EQ(copy["settings"]["photons_per_pass"], original["settings"]["photons_per_pass"]);
    EXPECT_EQ(copy["name"], "atrium");
    EXPECT_EQ(copy["labels"], json({"draft"}));
    EXPECT_EQ(copy["warnings"], json::array());
    EXPECT_TRUE(fs::is_regular_file(dataDir() / "jobs" / copy["id"].get<std::string>() / "meshes" / "tri.obj"));
    // Both scenes read back exactly as sent.
    for (const json& job : {original, copy}) {
        httplib::Result text = client().Get(("/api/v1/jobs/" + job["id"].get<std::string>() + "/scene").c_str());
        ASSERT_TRUE(text);
        EXPECT_EQ(text->status, 200);
        EXPECT_EQ(text->get_header_value("Content-Type"), "application/json");
        EXPECT_EQ(text->body, sceneText);
    }
    EXPECT_EQ(client().Post("/api/v1/jobs/0123456789abcdef/clone")->status, 404);
    EXPECT_EQ(client().Get("/api/v1/jobs/0123456789abcdef/scene")->status, 404);
    EXPECT_EQ(client().Post(("/api/v1/jobs/" + id + "/clone?label=bad%20label").c_str())->status, 400);
}

// The job's own log, line by line: its time, then what happened.
std::vector<std::string> logLines(const std::string& log) {
    std::vector<std::string> lines;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) {
        // "2026-12-01T21:00:00.123Z " then the event
        EXPECT_TRUE(line.size() > 25 && line[4] == '-' && line[10] == 'T' && line[23] == 'Z' && line[24] == ' ') << line;
        lines.push_back(line.substr(25));
    }
    return lines;
}

TEST_F(ActionsTest, TheLogSaysWhatHappenedToTheJob) {
    startServer({"--workers", "1"});
    httplib::MultipartFormDataItems items{{"scene", smallScene(3, 2000).dump(), "", "application/json"},
                                          {"extra", "x", "notes.txt", "text/plain"}};
    json job = json::parse(client().Post("/api/v1/jobs?seed=7", items)->body);
    const std::string id = job["id"];
    json done = waitForStatus(id, "completed");
    httplib::Result r = client().Get(("/api/v1/jobs/" + id + "/log").c_str());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_EQ(r->get_header_value("Content-Type"), "text/plain; charset=utf-8");
    std::vector<std::string> lines = logLines(r->body);
    ASSERT_EQ(lines.size(), 4u) << r->body;
    EXPECT_EQ(lines[0], "accepted from 127.0.0.1: 32x32, 3 passes, photons_per_pass 2000, seed 7, sppm, priority 0");
    EXPECT_EQ(lines[1], "warning: asset \"notes.txt\" is not used by the scene and was not stored");
    EXPECT_EQ(lines[2], "started");
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, "%.1f", done["elapsed_seconds"].get<double>());
    EXPECT_EQ(lines[3], "completed after 3 passes, " + std::string(elapsed) + " s of rendering");
    EXPECT_EQ(client().Get("/api/v1/jobs/0123456789abcdef/log")->status, 404);
}

TEST_F(ActionsTest, TheLogTellsOfAStopAndTheResumption) {
    startServer({"--workers", "1"});
    std::string id = submitOk(longScene());
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 1; });
    ASSERT_EQ(stopServer(), 0);
    startServer({"--workers", "1"});
    // A pass after the restart: the resumption is logged before the first pass.
    waitFor(id, [](const json& j) { return j["status"] == "running" && j["pass"].get<int>() >= 1; });
    ASSERT_EQ(client().Post("/api/v1/jobs/" + id + "/cancel")->status, 202);
    waitForStatus(id, "cancelled");
    std::vector<std::string> lines = logLines(client().Get(("/api/v1/jobs/" + id + "/log").c_str())->body);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[1], "started");
    EXPECT_EQ(lines[2].rfind("interrupted by the server stopping after pass ", 0), 0u) << lines[2];
    EXPECT_EQ(lines[3].rfind("resumed from its checkpoint after pass ", 0), 0u) << lines[3];
    EXPECT_EQ(lines[4], "cancel requested; the render stops after its current pass");
    EXPECT_EQ(lines[5].rfind("cancelled after ", 0), 0u) << lines[5];
}

// Pausing keeps the render's state: paused after a pass (its image still served), nothing
// rendered while paused, and resumed from that pass; a queued job pauses at once and stays
// out of the queue until resumed.
TEST_F(ActionsTest, APausedJobGoesOnFromItsPassWhenResumed) {
    startServer({"--workers", "1"});
    std::string id = submitOk(longScene());
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 1; });
    std::string waiting = submitOk(smallScene(2, 2000));
    httplib::Result queuedPause = client().Post("/api/v1/jobs/" + waiting + "/pause");
    ASSERT_EQ(queuedPause->status, 200);
    EXPECT_EQ(json::parse(queuedPause->body)["status"], "paused");
    ASSERT_EQ(client().Post("/api/v1/jobs/" + id + "/pause")->status, 202);
    json paused = waitForStatus(id, "paused");
    const int at = paused["pass"];
    EXPECT_GE(at, 1);
    httplib::Result image = client().Get(("/api/v1/jobs/" + id + "/image?format=exr").c_str());
    ASSERT_EQ(image->status, 200);
    EXPECT_EQ(image->get_header_value("X-Photon-Pass"), std::to_string(at));
    // The worker is free, yet the paused queued job does not start.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_EQ(getJob(id)["pass"], at);
    EXPECT_EQ(getJob(waiting)["status"], "paused");
    httplib::Result resumed = client().Post("/api/v1/jobs/" + id + "/resume");
    ASSERT_EQ(resumed->status, 200);
    EXPECT_EQ(json::parse(resumed->body)["status"], "queued");
    waitFor(id, [&](const json& j) { return j["status"] == "running" && j["pass"].get<int>() > at; });
    EXPECT_EQ(client().Post("/api/v1/jobs/" + id + "/resume")->status, 409);
    ASSERT_EQ(client().Post("/api/v1/jobs/" + id + "/cancel")->status, 202);
    waitForStatus(id, "cancelled");
    EXPECT_EQ(client().Post("/api/v1/jobs/" + id + "/pause")->status, 409);
    ASSERT_EQ(client().Post("/api/v1/jobs/" + waiting + "/resume")->status, 200);
    waitForStatus(waiting, "completed");
    std::vector<std::string> lines = logLines(client().Get(("/api/v1/jobs/" + id + "/log").c_str())->body);
    ASSERT_GE(lines.size(), 7u);
    EXPECT_EQ(lines[2], "pause requested; the render stops after its current pass");
    EXPECT_EQ(lines[3], "paused after pass " + std::to_string(at));
    EXPECT_EQ(lines[4], "resumed: queued again");
    EXPECT_EQ(lines[5], "resumed from its checkpoint after pass " + std::to_string(at));
}

// More passes of a completed job render on from its checkpoint: the result is the render
// of that many passes from the start, value for value.
TEST_F(ActionsTest, MorePassesOfACompletedJobEqualALongerRender) {
    startServer({"--workers", "1"});
    std::string id = submitOk(smallScene(2, 2000));
    waitForStatus(id, "completed");
    httplib::Result more = client().Post(("/api/v1/jobs/" + id + "/continue?passes=2").c_str());
    ASSERT_EQ(more->status, 200) << more->body;
    json queued = json::parse(more->body);
    EXPECT_EQ(queued["status"], "queued");
    EXPECT_EQ(queued["settings"]["passes"], 4);
    EXPECT_EQ(queued["finished_at"], nullptr);
    json done = waitFor(id, [](const json& j) { return j["status"] == "completed"; });
    EXPECT_EQ(done["pass"], 4);
    Image served = decodeImage(client().Get(("/api/v1/jobs/" + id + "/image?format=exr").c_str())->body, "exr");
    Image direct = renderInProcess(smallScene(4, 2000));
    ASSERT_EQ(served.rgb.size(), direct.rgb.size());
    size_t differing = 0;
    for (size_t i = 0; i < direct.rgb.size(); ++i) differing += served.rgb[i] != direct.rgb[i];
    EXPECT_EQ(differing, 0u) << "of " << direct.rgb.size() << " channel values";
    EXPECT_EQ(getJob(id)["settings"]["passes"], 4);  // stored
    // Only a completed job, and at least one pass.
    EXPECT_EQ(client().Post(("/api/v1/jobs/" + id + "/continue").c_str())->status, 400);
    std::string cancelled = submitOk(longScene());
    waitForStatus(cancelled, "running");
    EXPECT_EQ(client().Post(("/api/v1/jobs/" + cancelled + "/continue?passes=1").c_str())->status, 409);
    client().Post("/api/v1/jobs/" + cancelled + "/cancel");
}

TEST_F(ActionsTest, TheServicesOwnFileNamesAreNotAssets) {
    startServer({"--workers", "0"});
    for (const char* name : {"checkpoint.bin", "job.log", "image.png.tmp"}) {
        httplib::MultipartFormDataItems items{{"scene", smallScene().dump(), "", "application/json"},
                                              {"asset", "x", name, "application/octet-stream"}};
        httplib::Result r = client().Post("/api/v1/jobs", items);
        EXPECT_EQ(r->status, 400) << name;
        EXPECT_EQ(problemOf(r)["detail"], std::string("asset name \"") + name + "\" is reserved: part \"asset\" (file name \"" +
                                               name + "\")");
    }
}

}  // namespace
}  // namespace photon::test
