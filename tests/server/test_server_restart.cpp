// Jobs survive a restart: finished ones keep their records and images, queued ones run,
// interrupted ones resume from their checkpoint.
#include <photon/render.h>
#include <fstream>
#include <future>
#include <thread>
#include <utility>
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
    // Each follower says when its stream's first bytes arrived, and how the stream ended.
    struct Follower {
        std::promise<void> connected;
        bool endedByServer = false;
    };
    auto follow = [&](const std::string& path, Follower& f) {
        bool first = true;
        httplib::Result result = client().Get(path.c_str(), [&](const char*, size_t) {
            if (std::exchange(first, false)) f.connected.set_value();
            return true;
        });
        // A stream the server ends is a whole chunked response: 200 and no transport error.
        f.endedByServer = result && result->status == 200;
    };
    Follower events, frames;
    std::future<void> eventsConnected = events.connected.get_future(), framesConnected = frames.connected.get_future();
    std::thread eventThread(follow, "/api/v1/jobs/" + id + "/events", std::ref(events));
    std::thread frameThread(follow, "/api/v1/jobs/" + id + "/stream", std::ref(frames));
    EXPECT_EQ(eventsConnected.wait_for(std::chrono::seconds(30)), std::future_status::ready);
    EXPECT_EQ(framesConnected.wait_for(std::chrono::seconds(30)), std::future_status::ready);
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(stopServer(), 0);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    eventThread.join();
    frameThread.join();
    EXPECT_TRUE(events.endedByServer);
    EXPECT_TRUE(frames.endedByServer);
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

// A job of 200k photons per pass at 32x32, with as many passes as take this machine about
// six seconds (so that it is still running after its first checkpoint, written after a
// second, however many cores render it), is interrupted past its third pass: killed with
// kill -9 once it has a checkpoint, or stopped with SIGTERM (which saves one); then the
// server starts again.
class CrashTest : public ServerTest {
protected:
    static constexpr int64_t kPhotonsPerPass = 200000;

    static int passesLasting(double seconds) { return test::passesLasting(seconds, kPhotonsPerPass, 32); }

    std::string killWithACheckpoint(int passes) {
        std::string id = startAndWaitForPass3(passes, "1", true);
        killServer();  // nothing is saved on the way out
        return id;
    }

    // The job's checkpoint comes from the stop itself: periodic ones are an hour apart.
    std::string stopGracefully(int passes) {
        std::string id = startAndWaitForPass3(passes, "3600", false);
        EXPECT_FALSE(std::filesystem::exists(checkpoint_));
        EXPECT_EQ(stopServer(), 0);
        EXPECT_TRUE(std::filesystem::exists(checkpoint_));
        return id;
    }

    std::string startAndWaitForPass3(int passes, const std::string& checkpointSeconds, bool withCheckpoint) {
        scene_ = smallScene(passes, kPhotonsPerPass, 32);
        startServer({"--checkpoint-seconds", checkpointSeconds});
        std::string id = submitOk(scene_);
        checkpoint_ = dataDir() / "jobs" / id / "checkpoint.bin";
        json before = waitFor(
            id,
            [&](const json& j) {
                return j["pass"].get<int>() >= 3 && (!withCheckpoint || std::filesystem::exists(checkpoint_));
            },
            std::chrono::seconds(60));
        EXPECT_LT(before["pass"].get<int>(), passes) << "the job finished before it could be interrupted";
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
    const int total = passesLasting(6);
    std::string id = killWithACheckpoint(total);
    std::vector<int> passes = passesAfterRestart(id);
    ASSERT_FALSE(passes.empty());
    EXPECT_GT(passes.front(), 1) << "resumed from pass 0";
    EXPECT_EQ(passes.back(), total);
    EXPECT_TRUE(std::filesystem::exists(checkpoint_));  // kept by the completed job, for more passes
    expectTheImageOfAnUninterruptedRender(id);
}

TEST_F(CrashTest, AServerStoppedWithSigtermResumesTheJobPastItsFirstPass) {
    const int total = passesLasting(6);
    std::string id = stopGracefully(total);
    std::vector<int> passes = passesAfterRestart(id);
    ASSERT_FALSE(passes.empty());
    EXPECT_GT(passes.front(), 3) << "did not resume from the checkpoint saved at the stop";
    EXPECT_EQ(passes.back(), total);
    expectTheImageOfAnUninterruptedRender(id);
}

TEST_F(CrashTest, ADamagedCheckpointIsDiscardedAndTheJobStartsOver) {
    const int total = passesLasting(6);
    std::string id = killWithACheckpoint(total);
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
    EXPECT_EQ(passes.back(), total);
    expectTheImageOfAnUninterruptedRender(id);
}

}  // namespace
}  // namespace photon::test
