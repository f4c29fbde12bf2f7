// photon-server --redis end to end: a job whose passes are independent is rendered in batches
// by two photon-worker processes and served as the image one process renders, bit for bit;
// any other job is rendered whole by one worker, and moves to another when its worker dies.
#include "redis_process.h"
#include <cstring>
#include <filesystem>
#include <unistd.h>
#include <optional>
#include <set>
#include <thread>
#include "../server_fixture.h"

namespace photon::test {
namespace {

class FarmServerTest : public ServerTest {
protected:
    bool bitIdentical(const Image& a, const Image& b) {
        return a.rgb.size() == b.rgb.size() &&
               std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
    }
    Image servedExr(const std::string& id) {
        httplib::Result r = client().Get(("/api/v1/jobs/" + id + "/image?format=exr").c_str(), auth());
        EXPECT_EQ(r->status, 200);
        return decodeImage(r->body, ".exr");
    }
    RedisProcess redis_;
};

TEST_F(FarmServerTest, IndependentPassesRenderOnTheWorkersAsInOneProcess) {
    WorkerProcess a(redis_.address(), "a", PHOTON_WORKER_BINARY), b(redis_.address(), "b", PHOTON_WORKER_BINARY);
    startServer({"--redis", redis_.address().url(), "--farm-batch-passes", "2", "--workers", "0"});
    json scene = smallScene(6, 5000, 32);
    scene["render"]["radius_schedule"] = "global";
    const std::string id = submitOk(scene);
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                       std::chrono::seconds(60));
    ASSERT_EQ(job["status"], "completed") << job.dump();
    EXPECT_EQ(job["pass"], 6);
    EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene)));
    httplib::Result log = client().Get(("/api/v1/jobs/" + id + "/log").c_str(), auth());
    EXPECT_NE(log->body.find("on the render farm from pass 0, 2 passes a batch"), std::string::npos) << log->body;

    // The workers and the farm's figures.
    json workers = json::parse(client().Get("/api/v1/workers", auth())->body);
    EXPECT_EQ(workers["farm"], true);
    EXPECT_EQ(workers["queue_depth"], 0);
    std::set<std::string> names;
    int64_t batches = 0;
    for (const json& w : workers["workers"]) {
        names.insert(w["name"].get<std::string>());
        batches += w["batches"].get<int64_t>();
        EXPECT_EQ(w["threads"], 1);
        EXPECT_EQ(w["redeliveries"], 0);
    }
    EXPECT_EQ(names, (std::set<std::string>{"a", "b"}));
    EXPECT_EQ(batches, 3);
    const std::string metrics = client().Get("/metrics", auth())->body;
    EXPECT_NE(metrics.find("\nphoton_farm_workers 2\n"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("\nphoton_farm_batch_seconds_count 3\n"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("\nphoton_farm_duplicate_results_total 0\n"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("photon_farm_worker_batches{worker=\"a\"}"), std::string::npos) << metrics;

    // Per-pixel statistics cannot be split: the job goes whole to one worker.
    json perPixel = smallScene(3, 5000, 32);
    const std::string whole = submitOk(perPixel);
    ASSERT_EQ(waitForStatus(whole, "completed")["pass"], 3);
    EXPECT_TRUE(bitIdentical(servedExr(whole), renderInProcess(perPixel)));
    log = client().Get(("/api/v1/jobs/" + whole + "/log").c_str(), auth());
    EXPECT_NE(log->body.find("on the render farm as a whole job from pass 0"), std::string::npos) << log->body;
}

// Many small jobs over three workers: each completes with its one-process image, and the
// workers rendered each item once (6 jobs of 2 batches and 3 whole jobs of three methods: 15
// items, no duplicate results).
TEST_F(FarmServerTest, ManySmallJobsOverThreeWorkersEachRenderOnce) {
    WorkerProcess a(redis_.address(), "a", PHOTON_WORKER_BINARY), b(redis_.address(), "b", PHOTON_WORKER_BINARY),
        c(redis_.address(), "c", PHOTON_WORKER_BINARY);
    startServer({"--redis", redis_.address().url(), "--farm-batch-passes", "2", "--workers", "0", "--farm-jobs", "3"});
    std::vector<std::pair<std::string, json>> jobs;
    for (int seed = 1; seed <= 6; ++seed) {
        json scene = smallScene(4, 3000, 24);
        scene["render"]["radius_schedule"] = "global";
        scene["render"]["seed"] = seed;
        jobs.emplace_back(submitOk(scene), scene);
    }
    for (const char* integrator : {"sppm", "path", "photonmap"}) {
        json scene = smallScene(3, 3000, 24);
        scene["render"]["integrator"] = integrator;
        jobs.emplace_back(submitOk(scene), scene);
    }
    for (const auto& [id, scene] : jobs) {
        // A guard against a hang, not a speed test: under ThreadSanitizer the server, three
        // workers and the test share one CPU, and with the machine busy the ninth job waited
        // over a minute at pass 0 for a worker.
        json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                           std::chrono::seconds(240));
        ASSERT_EQ(job["status"], "completed") << job.dump();
        EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene))) << id;
        // A whole job's figures come from its worker.
        if (scene["render"].value("integrator", "") == "photonmap")
            EXPECT_GT(job["figures"]["global_map_photons"].get<int64_t>(), 0) << job.dump();
    }
    int64_t batches = 0;
    const json workers = json::parse(client().Get("/api/v1/workers", auth())->body);
    for (const json& w : workers["workers"]) batches += w["batches"].get<int64_t>();
    EXPECT_EQ(batches, 15) << workers.dump();
    const std::string metrics = client().Get("/metrics", auth())->body;
    EXPECT_NE(metrics.find("\nphoton_farm_batch_seconds_count 12\n"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("\nphoton_farm_duplicate_results_total 0\n"), std::string::npos) << metrics;
}

TEST_F(FarmServerTest, WithoutAFarmTheWorkerListIsEmpty) {
    startServer();
    httplib::Result r = client().Get("/api/v1/workers", auth());
    ASSERT_EQ(r->status, 200);
    EXPECT_EQ(json::parse(r->body), json::parse(R"({"farm": false, "queue_depth": 0, "workers": []})"));
    EXPECT_EQ(client().Get("/metrics", auth())->body.find("photon_farm"), std::string::npos);
}

// The server is killed (SIGKILL) while the farm renders its job; started again, it asks the
// farm only for the passes its checkpoint does not hold, and the image is still one
// process's.
TEST_F(FarmServerTest, ARestartedServerReissuesOnlyWhatItHadNotMerged) {
    WorkerProcess worker(redis_.address(), "w", PHOTON_WORKER_BINARY);
    const std::vector<std::string> args = {"--redis", redis_.address().url(), "--farm-batch-passes", "2",
                                           "--checkpoint-seconds", "1", "--workers", "0"};
    startServer(args);
    json scene = smallScene(120, 20000, 32);
    scene["render"]["radius_schedule"] = "global";
    const std::string id = submitOk(scene);
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 10; }, std::chrono::seconds(60));
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // a checkpoint after pass 10
    killServer();
    startServer(args);
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                       std::chrono::seconds(120));
    ASSERT_EQ(job["status"], "completed") << job.dump();
    const std::string log = client().Get(("/api/v1/jobs/" + id + "/log").c_str(), auth())->body;
    const std::string second = "on the render farm from pass ";
    const size_t at = log.rfind(second);
    ASSERT_NE(at, std::string::npos) << log;
    const int resumedFrom = std::stoi(log.substr(at + second.size()));
    EXPECT_GE(resumedFrom, 10) << log;
    EXPECT_LT(resumedFrom, 120) << log;
    EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene)));
}

// A whole job's worker is killed (SIGKILL) mid-render: another worker takes its item over
// after --claim-after, resumes from the checkpoint the first one left in Redis, and the job
// completes with one process's image.
TEST_F(FarmServerTest, AWholeJobMovesToAnotherWorkerWhenItsWorkerDies) {
    std::optional<WorkerProcess> first;
    first.emplace(redis_.address(), "first", PHOTON_WORKER_BINARY, "1");
    startServer({"--redis", redis_.address().url(), "--workers", "0", "--checkpoint-seconds", "1"});
    json scene = smallScene(1, 3000, 32);
    scene["render"]["integrator"] = "path";  // timed as such: its passes are far shorter than SPPM's
    scene["render"]["passes"] = passesLasting(8, scene);
    const std::string id = submitOk(scene);
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 4; }, std::chrono::seconds(60));
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // a checkpoint on the way
    first->kill();
    const int passBefore = json::parse(client().Get(("/api/v1/jobs/" + id).c_str(), auth())->body)["pass"];
    WorkerProcess second(redis_.address(), "second", PHOTON_WORKER_BINARY, "1");
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                       std::chrono::seconds(120));
    ASSERT_EQ(job["status"], "completed") << job.dump();
    EXPECT_GE(passBefore, 4);
    EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene)));
    const json workers = json::parse(client().Get("/api/v1/workers", auth())->body);
    ASSERT_EQ(workers["workers"].size(), 1u) << workers.dump();
    EXPECT_EQ(workers["workers"][0]["name"], "second");
    EXPECT_EQ(workers["workers"][0]["redeliveries"], 1);
    EXPECT_EQ(workers["workers"][0]["batches"], 1);
}

// Pause reaches the worker rendering a whole job; resumed, the job goes on from its last
// checkpoint and completes with one process's image. Cancel stops it within moments.
TEST_F(FarmServerTest, AWholeJobPausesResumesAndCancelsOnTheFarm) {
    WorkerProcess worker(redis_.address(), "w", PHOTON_WORKER_BINARY);
    startServer({"--redis", redis_.address().url(), "--workers", "0", "--checkpoint-seconds", "1"});
    json scene = smallScene(passesLasting(6, 3000, 32), 3000, 32);
    const std::string id = submitOk(scene);
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 3; }, std::chrono::seconds(60));
    std::this_thread::sleep_for(std::chrono::milliseconds(1200));
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + id + "/pause").c_str(), auth(), "", "application/json")->status, 202);
    json paused = waitForStatus(id, "paused");
    auto idle = [&] {
        const json w = json::parse(client().Get("/api/v1/workers", auth())->body)["workers"];
        return w.size() == 1 && w[0]["busy"] == false;
    };
    for (int i = 0; i < 100 && !idle(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_TRUE(idle());
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + id + "/resume").c_str(), auth(), "", "application/json")->status, 200);
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                       std::chrono::seconds(120));
    ASSERT_EQ(job["status"], "completed") << job.dump();
    EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene)));

    const std::string cancelled = submitOk(longScene());
    waitFor(cancelled, [](const json& j) { return j["pass"].get<int>() >= 1; }, std::chrono::seconds(60));
    ASSERT_EQ(client().Post(("/api/v1/jobs/" + cancelled + "/cancel").c_str(), auth(), "", "application/json")->status,
              202);
    waitForStatus(cancelled, "cancelled");
    for (int i = 0; i < 100 && !idle(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_TRUE(idle());
}

// With --redis and workers of its own, one server is a farm of one: it renders every job
// through Redis, as any worker would.
TEST_F(FarmServerTest, AServerWithItsOwnWorkersIsAFarmOfOne) {
    startServer({"--redis", redis_.address().url(), "--workers", "1"});
    json batches = smallScene(4, 3000, 24);
    batches["render"]["radius_schedule"] = "global";
    json whole = smallScene(3, 3000, 24);
    whole["render"]["integrator"] = "path";
    const std::string a = submitOk(batches), b = submitOk(whole);
    const json batchJob = waitForStatus(a, "completed"), wholeJob = waitForStatus(b, "completed");
    ASSERT_EQ(batchJob["pass"], 4);
    ASSERT_EQ(wholeJob["pass"], 3);
    // Kept passes: a batch of four merges as pass 4; a whole job reports passes 1, 2, 4, ...
    EXPECT_EQ(batchJob["kept_passes"], json::parse("[4]"));
    EXPECT_EQ(wholeJob["kept_passes"], json::parse("[1, 2]"));
    EXPECT_EQ(wholeJob["figures"]["samples_per_pixel"], 3);
    EXPECT_TRUE(bitIdentical(servedExr(a), renderInProcess(batches)));
    EXPECT_TRUE(bitIdentical(servedExr(b), renderInProcess(whole)));
    const json workers = json::parse(client().Get("/api/v1/workers", auth())->body)["workers"];
    ASSERT_EQ(workers.size(), 1u) << workers.dump();
    const std::string name = workers[0]["name"];
    EXPECT_EQ(name.substr(name.size() - 9), "-server-1") << name;
    EXPECT_EQ(workers[0]["batches"], 1 + 1);  // one batch of 4 passes (the default), one whole job
}

// A job of batches ends at its time limit as a local render does, after the batch that
// crosses it; the batches still on the farm are dropped.
TEST_F(FarmServerTest, AJobOfBatchesStopsAtItsTimeLimit) {
    startServer({"--redis", redis_.address().url(), "--workers", "1", "--farm-batch-passes", "1"});
    json scene = smallScene(100000, 3000, 32);
    scene["render"]["radius_schedule"] = "global";
    scene["render"]["time_limit"] = 1.5;
    const std::string id = submitOk(scene);
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                       std::chrono::seconds(60));
    ASSERT_EQ(job["status"], "completed") << job.dump();
    EXPECT_GT(job["pass"].get<int>(), 0);
    EXPECT_LT(job["pass"].get<int>(), 100000);
    EXPECT_GE(job["elapsed_seconds"].get<double>(), 1.5);
    EXPECT_EQ(json::parse(client().Get("/api/v1/workers", auth())->body)["queue_depth"], 0);
}

// Redis (with its append-only file) is restarted while the farm renders a job: the worker
// and the server wait it out, and the job completes with one process's image.
class FarmRedisRestartTest : public FarmServerTest {
protected:
    static std::filesystem::path appendOnlyDir() {
        auto dir = std::filesystem::temp_directory_path() / ("photon-aof-" + std::to_string(getpid()));
        std::filesystem::create_directories(dir);
        return dir;
    }
    ~FarmRedisRestartTest() override { std::filesystem::remove_all(aof_); }
    std::filesystem::path aof_ = appendOnlyDir();
    RedisProcess durable_{aof_.string()};
};

TEST_F(FarmRedisRestartTest, AJobOutlivesARedisRestart) {
    WorkerProcess worker(durable_.address(), "w", PHOTON_WORKER_BINARY, "1");
    startServer({"--redis", durable_.address().url(), "--farm-batch-passes", "2", "--workers", "0"});
    json scene = smallScene(60, 20000, 32);
    scene["render"]["radius_schedule"] = "global";
    const std::string id = submitOk(scene);
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 6; }, std::chrono::seconds(60));
    durable_.restart();
    json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                       std::chrono::seconds(120));
    ASSERT_EQ(job["status"], "completed") << job.dump();
    EXPECT_EQ(job["pass"], 60);
    EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene)));
}

}  // namespace
}  // namespace photon::test
