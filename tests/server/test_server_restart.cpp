// Jobs survive a restart: finished ones keep their records and images, queued ones run,
// interrupted ones resume from their checkpoint.
#include <atomic>
#include <fstream>
#include <thread>
#include "server_fixture.h"

namespace photon::test {
namespace {

class RestartTest : public ServerTest {};

TEST_F(RestartTest, JobsSurviveARestart) {
    startServer();
    std::string done = submitOk(smallScene());
    ASSERT_EQ(waitForStatus(done, "completed")["status"], "completed");
    std::string interrupted = submitOk(longScene());
    ASSERT_GE(waitFor(interrupted, [](const json& j) { return j["pass"] >= 1; })["pass"], 1);
    EXPECT_EQ(stopServer(), 0);

    // Second run renders nothing: everything is as the first run left it.
    startServer({"--workers", "0"});
    json page = json::parse(client().Get("/api/v1/jobs")->body);
    EXPECT_EQ(page["total"], 2);
    json first = getJob(done);
    EXPECT_EQ(first["status"], "completed");
    EXPECT_EQ(first["pass"], 3);
    json second = getJob(interrupted);
    EXPECT_EQ(second["status"], "queued");
    EXPECT_EQ(second["pass"], 0);
    EXPECT_TRUE(second["started_at"].is_null());
    httplib::Result image = client().Get(("/api/v1/jobs/" + done + "/image?format=exr").c_str());
    ASSERT_TRUE(image);
    EXPECT_EQ(image->status, 200);
    EXPECT_EQ(image->get_header_value("ETag"), "\"" + done + "-3-exr\"");
    EXPECT_EQ(decodeImage(image->body, "exr").width, 32);
    // Submitted now, run after the next restart; its priority puts it before the long job.
    std::string later = submitOk(smallScene(), "?priority=5");
    EXPECT_EQ(stopServer(), 0);

    startServer();
    json ran = waitForStatus(later, "completed");
    EXPECT_EQ(ran["status"], "completed");
    EXPECT_EQ(ran["pass"], 3);
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + later + "/image").c_str())->status, 200);
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + done + "/image").c_str())->status, 200);
    std::vector<SseEvent> events = followEvents(done);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].type, "done");
    EXPECT_EQ(events[0].data["pass"], 3);
    // The long job runs again once the priority job is done.
    EXPECT_EQ(waitForStatus(interrupted, "running")["status"], "running");
}

TEST_F(RestartTest, StoppingEndsOpenStreamsPromptly) {
    startServer();
    std::string id = submitOk(longScene());
    waitForStatus(id, "running");
    std::atomic<int> streamsEnded{0};
    auto follow = [&](const std::string& path) {
        client().Get(path.c_str(), [](const char*, size_t) { return true; });
        ++streamsEnded;
    };
    std::thread events(follow, "/api/v1/jobs/" + id + "/events");
    std::thread frames(follow, "/api/v1/jobs/" + id + "/stream");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(stopServer(), 0);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    events.join();
    frames.join();
    EXPECT_EQ(streamsEnded, 2);
}

TEST_F(RestartTest, AJobWhoseSceneVanishedFails) {
    startServer({"--workers", "0"});
    std::string id = submitOk(smallScene());
    stopServer();
    std::filesystem::remove(dataDir() / "jobs" / id / "scene.json");
    startServer();
    json job = waitForStatus(id, "failed");
    EXPECT_EQ(job["status"], "failed");
    EXPECT_TRUE(job["error"].is_string() && !job["error"].get<std::string>().empty()) << job;
    std::vector<SseEvent> events = followEvents(id);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].type, "failed");
    EXPECT_EQ(client().Get(("/api/v1/jobs/" + id + "/image").c_str())->status, 404);
    EXPECT_EQ(client().Delete(("/api/v1/jobs/" + id).c_str())->status, 204);
}

TEST_F(RestartTest, SecondServerOnTheSameDataDirectoryRefusesToStart) {
    startServer({"--workers", "0"});
    ServerProcess second;
    EXPECT_THROW(second.start({"--data", dataDir().string()}), std::runtime_error);
}

}  // namespace
}  // namespace photon::test

namespace photon::test {
namespace {

// A job of `passes` passes of 200k photons at 32x32 (long enough to be killed in the
// middle) is killed with kill -9 once it has a checkpoint; then the server starts again.
class CrashTest : public ServerTest {
protected:
    std::string killWithACheckpoint(int passes) {
        scene_ = smallScene(passes, 200000, 32);
        startServer({"--checkpoint-seconds", "1"});
        std::string id = submitOk(scene_);
        checkpoint_ = dataDir() / "jobs" / id / "checkpoint.bin";
        json before = waitFor(
            id, [&](const json& j) { return j["pass"].get<int>() >= 3 && std::filesystem::exists(checkpoint_); },
            std::chrono::seconds(60));
        EXPECT_TRUE(std::filesystem::exists(checkpoint_));
        EXPECT_LT(before["pass"].get<int>(), passes) << "the job finished before it could be killed";
        killServer();  // nothing is saved on the way out
        return id;
    }

    // Restarts the server and follows the job to its end: the passes it reported.
    std::vector<int> passesAfterRestart(const std::string& id) {
        startServer({"--checkpoint-seconds", "1"});
        std::vector<SseEvent> events = followEvents(id, {{"Last-Event-ID", "0"}});
        std::vector<int> passes;
        for (const SseEvent& e : events)
            if (e.type == "progress" && e.data["pass"].get<int>() > 0) passes.push_back(e.data["pass"].get<int>());
        EXPECT_TRUE(!events.empty() && events.back().type == "done");
        return passes;
    }

    void expectTheImageOfAnUninterruptedRender(const std::string& id) {
        httplib::Result exr = client().Get(("/api/v1/jobs/" + id + "/image?format=exr").c_str());
        ASSERT_TRUE(exr);
        ASSERT_EQ(exr->status, 200);
        EXPECT_TRUE(decodeImage(exr->body, "exr").rgb == renderInProcess(scene_).rgb);
    }

    json scene_;
    std::filesystem::path checkpoint_;
};

TEST_F(CrashTest, AKilledServerResumesTheJobFromItsLastCheckpoint) {
    std::string id = killWithACheckpoint(200);
    std::vector<int> passes = passesAfterRestart(id);
    ASSERT_FALSE(passes.empty());
    EXPECT_GT(passes.front(), 1) << "resumed from pass 0";
    EXPECT_EQ(passes.back(), 200);
    EXPECT_FALSE(std::filesystem::exists(checkpoint_));  // removed once the job is done
    expectTheImageOfAnUninterruptedRender(id);
}

TEST_F(CrashTest, ADamagedCheckpointIsDiscardedAndTheJobStartsOver) {
    std::string id = killWithACheckpoint(100);
    {  // one bit flipped in the middle of the pixel data, as a failing disk might
        const auto middle = static_cast<std::streamoff>(std::filesystem::file_size(checkpoint_) / 2);
        std::fstream file(checkpoint_, std::ios::in | std::ios::out | std::ios::binary);
        file.seekg(middle);
        char byte = 0;
        file.get(byte);
        file.seekp(middle);
        file.put(static_cast<char>(byte ^ 0x10));
    }
    std::vector<int> passes = passesAfterRestart(id);
    ASSERT_FALSE(passes.empty());
    EXPECT_EQ(passes.front(), 1) << "resumed from a damaged checkpoint";
    EXPECT_EQ(passes.back(), 100);
    expectTheImageOfAnUninterruptedRender(id);
}

}  // namespace
}  // namespace photon::test
