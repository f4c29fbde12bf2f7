// photon-server --redis end to end: a job whose passes are independent is rendered by two
// photon-worker processes and served as the image one process renders, bit for bit; a job
// with per-pixel statistics still renders in the server.
#include "redis_process.h"
#include <cstring>
#include <filesystem>
#include <unistd.h>
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
    startServer({"--redis", redis_.address().url(), "--farm-batch-passes", "2"});
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

    // Per-pixel statistics cannot be split: rendered here, the same way.
    json perPixel = smallScene(3, 5000, 32);
    const std::string local = submitOk(perPixel);
    ASSERT_EQ(waitForStatus(local, "completed")["pass"], 3);
    EXPECT_TRUE(bitIdentical(servedExr(local), renderInProcess(perPixel)));
}

// Many small jobs over three workers: each completes with its one-process image, and the
// workers rendered each batch once (12 batches, no duplicate results).
TEST_F(FarmServerTest, ManySmallJobsOverThreeWorkersEachRenderOnce) {
    WorkerProcess a(redis_.address(), "a", PHOTON_WORKER_BINARY), b(redis_.address(), "b", PHOTON_WORKER_BINARY),
        c(redis_.address(), "c", PHOTON_WORKER_BINARY);
    startServer({"--redis", redis_.address().url(), "--farm-batch-passes", "2", "--workers", "3"});
    std::vector<std::pair<std::string, json>> jobs;
    for (int seed = 1; seed <= 6; ++seed) {
        json scene = smallScene(4, 3000, 24);
        scene["render"]["radius_schedule"] = "global";
        scene["render"]["seed"] = seed;
        jobs.emplace_back(submitOk(scene), scene);
    }
    for (const auto& [id, scene] : jobs) {
        json job = waitFor(id, [](const json& j) { return j["status"] == "completed" || j["status"] == "failed"; },
                           std::chrono::seconds(60));
        ASSERT_EQ(job["status"], "completed") << job.dump();
        EXPECT_TRUE(bitIdentical(servedExr(id), renderInProcess(scene))) << id;
    }
    int64_t batches = 0;
    const json workers = json::parse(client().Get("/api/v1/workers", auth())->body);
    for (const json& w : workers["workers"]) batches += w["batches"].get<int64_t>();
    EXPECT_EQ(batches, 12) << workers.dump();
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
                                           "--checkpoint-seconds", "1"};
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
    startServer({"--redis", durable_.address().url(), "--farm-batch-passes", "2"});
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
