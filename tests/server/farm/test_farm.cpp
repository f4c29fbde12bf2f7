// The render farm on a real Redis: workers render a job's batches of independent passes and
// the coordinator's merge equals, bit for bit, one process rendering them; a worker killed
// mid-batch loses nothing (its item is claimed by another after claim-after) and a batch
// delivered twice is merged once; cancelling stops workers and drops the job's items; a
// scene that does not load comes back as an error, once per batch, and is not retried.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <photon/render.h>
#include "redis_process.h"
#include "server/farm/farm_coordinator.h"
#include "server/farm/farm_keys.h"
#include "server/farm/farm_worker.h"

namespace photon {
namespace {

using namespace std::chrono_literals;
using farm::BatchPlan;
using farm::FarmCoordinator;
using farm::FarmScene;
using farm::FarmWorker;
using farm::RedisClient;

class FarmTest : public testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() /
                  ("photon-farm-test-" + std::to_string(getpid()) + "-" +
                   testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(folder_);
        std::filesystem::create_directories(folder_ / "scene");
        std::filesystem::copy_file(std::filesystem::path(PHOTON_SOURCE_DIR) / "scenes/cornell-box.json",
                                   folder_ / "scene/cornell-box.json");
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    std::vector<SettingOverride> overrides(int passes, int64_t photons = 10000) const {
        return {{"camera.resolution", "[32, 32]"},
                {"render.passes", std::to_string(passes)},
                {"render.photons_per_pass", std::to_string(photons)},
                {"render.radius_schedule", "global"},
                {"render.seed", "5"}};
    }
    FarmScene scene(int passes, int64_t photons = 10000) const {
        return FarmScene::fromFolder(folder_ / "scene", "cornell-box.json", overrides(passes, photons));
    }
    Renderer renderer(int passes, int64_t photons = 10000) const {
        return Renderer(SceneFile::read(folder_ / "scene/cornell-box.json", overrides(passes, photons)));
    }
    farm::WorkerOptions workerOptions(const std::string& name, std::chrono::milliseconds claimAfter = 30s) const {
        farm::WorkerOptions o;
        o.redis = redis_.address();
        o.name = name;
        o.threads = 1;
        o.claimAfter = claimAfter;
        o.block = 100ms;
        o.scratch = folder_ / ("worker-" + name);
        return o;
    }
    // Collects until `batches` results of `job` were merged into `into` (or 60 s passed).
    std::vector<FarmCoordinator::Result> mergeAll(FarmCoordinator& coordinator, Renderer& into, int64_t batches) {
        std::vector<FarmCoordinator::Result> errors;
        int64_t merged = 0;
        const auto deadline = std::chrono::steady_clock::now() + 60s;
        while (merged + int64_t(errors.size()) < batches && std::chrono::steady_clock::now() < deadline)
            coordinator.collect(100ms, [&](FarmCoordinator::Result&& r) {
                if (!r.error.empty()) return errors.push_back(std::move(r));
                into.addPasses(r.sums);
                ++merged;
            });
        EXPECT_EQ(merged + int64_t(errors.size()), batches);
        return errors;
    }
    static bool bitIdentical(const Image& a, const Image& b) {
        return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
    }
    Image oneProcess(int passes) const {
        Renderer r = renderer(passes);
        for (int i = 0; i < passes; ++i) EXPECT_TRUE(r.renderPass(CancelToken{}));
        return r.rawSnapshot();
    }

    test::RedisProcess redis_;
    std::filesystem::path folder_;
};

// Runs a worker on its own thread until the object goes.
class WorkerThread {
public:
    explicit WorkerThread(farm::WorkerOptions options)
        : worker_(std::move(options)), thread_([this] { worker_.run(stop_); }) {}
    ~WorkerThread() { stop(); }
    // Stops after the step it is in; its counters are final then.
    void stop() {
        stop_.store(true);
        if (thread_.joinable()) thread_.join();
    }
    const FarmWorker::Counters& counters() const { return worker_.counters(); }

private:
    std::atomic<bool> stop_{false};
    FarmWorker worker_;
    std::thread thread_;
};

TEST_F(FarmTest, WorkersRenderAJobBitForBitAsOneProcess) {
    FarmCoordinator coordinator(redis_.address());
    coordinator.submit("job1", scene(12), BatchPlan{12, 3, 0, 2});
    EXPECT_EQ(coordinator.queueDepth(), 2);  // two batches ahead; one more as each comes back
    Renderer merged = renderer(12);
    {
        WorkerThread a(workerOptions("a")), b(workerOptions("b"));
        EXPECT_TRUE(mergeAll(coordinator, merged, 4).empty());
        a.stop(), b.stop();
        EXPECT_EQ(a.counters().batches + b.counters().batches, 4);
        EXPECT_EQ(a.counters().passes + b.counters().passes, 12);
    }
    EXPECT_EQ(merged.progress().pass, 12);
    EXPECT_TRUE(bitIdentical(merged.rawSnapshot(), oneProcess(12)));
    EXPECT_EQ(coordinator.queueDepth(), 0);  // done items are deleted
    EXPECT_EQ(coordinator.counters().duplicates, 0);
}

// A worker process is killed (SIGKILL) while it renders a batch; the item it held stays
// pending and a second worker claims it after claim-after. The job completes, and its image
// is one process's. A copy of a result (a re-delivery) is not merged again.
TEST_F(FarmTest, AKilledWorkersBatchIsClaimedAndTheJobCompletes) {
    FarmCoordinator coordinator(redis_.address());
    coordinator.submit("job2", scene(4, 200000), BatchPlan{4, 4});  // one long batch
    const std::string scratch = (folder_ / "doomed").string();
    pid_t doomed = fork();
    if (doomed == 0) {
        execl(PHOTON_WORKER_BINARY, PHOTON_WORKER_BINARY, "--redis", redis_.address().url().c_str(), "--name",
              "doomed", "--threads", "1", nullptr);
        _exit(127);
    }
    RedisClient redis(redis_.address());
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    while (redis.command({"HGET", farm::workerKey("doomed"), "item"}).string != "job2/0" &&
           std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(5ms);
    ASSERT_EQ(redis.command({"HGET", farm::workerKey("doomed"), "item"}).string, "job2/0");
    kill(doomed, SIGKILL);
    waitpid(doomed, nullptr, 0);
    EXPECT_EQ(coordinator.queueDepth(), 1);  // still there, pending for the dead worker

    Renderer merged = renderer(4, 200000);
    {
        WorkerThread rescuer(workerOptions("rescuer", 300ms));
        EXPECT_TRUE(mergeAll(coordinator, merged, 1).empty());
        rescuer.stop();
        EXPECT_EQ(rescuer.counters().claimed, 1);
    }
    Renderer one = renderer(4, 200000);
    for (int i = 0; i < 4; ++i) ASSERT_TRUE(one.renderPass(CancelToken{}));
    EXPECT_TRUE(bitIdentical(merged.rawSnapshot(), one.rawSnapshot()));

    // The same batch once more, as a slow worker would send it: dropped.
    std::optional<PassSums> again = one.renderPasses(0, 4, CancelToken{});
    redis.command({"XADD", farm::kResultStream, "*", "job", "job2", "batch", "0", "worker", "slow", "sums", again->encode()});
    EXPECT_EQ(coordinator.collect(500ms, [](FarmCoordinator::Result&&) { ADD_FAILURE() << "merged twice"; }), 0u);
    EXPECT_EQ(coordinator.counters().duplicates, 1);
}

// Cancelling reaches a worker inside its batch (between passes); forgetting the job drops
// the items still queued.
TEST_F(FarmTest, CancelStopsTheBatchAndForgetDropsTheItems) {
    FarmCoordinator coordinator(redis_.address());
    coordinator.submit("job3", scene(40, 100000), BatchPlan{40, 20});
    RedisClient redis(redis_.address());
    {
        WorkerThread worker(workerOptions("w"));
        const auto deadline = std::chrono::steady_clock::now() + 30s;
        while (redis.command({"HGET", farm::workerKey("w"), "item"}).string != "job3/0" &&
               std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(5ms);
        coordinator.cancel("job3");
        const auto stopBy = std::chrono::steady_clock::now() + 10s;
        while (worker.counters().cancelled + worker.counters().dropped < 2 && std::chrono::steady_clock::now() < stopBy)
            std::this_thread::sleep_for(10ms);
        EXPECT_EQ(worker.counters().cancelled, 1);  // the batch it was in
        EXPECT_EQ(worker.counters().dropped, 1);    // the one after
        EXPECT_EQ(worker.counters().batches, 0);
    }
    EXPECT_EQ(coordinator.collect(100ms, [](FarmCoordinator::Result&&) { ADD_FAILURE() << "a cancelled batch came back"; }), 0u);

    coordinator.submit("job4", scene(8), BatchPlan{8, 2});
    EXPECT_EQ(coordinator.queueDepth(), 4);
    coordinator.forget("job4");
    EXPECT_EQ(coordinator.queueDepth(), 0);
    EXPECT_EQ(redis.command({"EXISTS", farm::sceneKey("job4")}).integer, 0);
}

TEST_F(FarmTest, ASceneThatDoesNotLoadComesBackAsAnErrorOnce) {
    std::filesystem::create_directories(folder_ / "broken");
    std::ofstream(folder_ / "broken/cornell-box.json") << "{\"camera\": ";
    FarmCoordinator coordinator(redis_.address());
    coordinator.submit("job5", FarmScene::fromFolder(folder_ / "broken", "cornell-box.json", overrides(4)),
                       BatchPlan{4, 2});
    Renderer unused = renderer(4);
    std::vector<FarmCoordinator::Result> errors;
    {
        WorkerThread worker(workerOptions("w"));
        errors = mergeAll(coordinator, unused, 2);
    }
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0].worker, "w");
    EXPECT_EQ(errors[0].error.rfind("malformed JSON: parse error at line 1, column 12", 0), 0u) << errors[0].error;
    EXPECT_EQ(coordinator.queueDepth(), 0);  // not retried
}

TEST(RedisAddress, ParsesAndNamesWhatIsWrong) {
    farm::RedisAddress a = farm::RedisAddress::parse("redis://10.0.0.7:6380");
    EXPECT_EQ(a.host, "10.0.0.7");
    EXPECT_EQ(a.port, 6380);
    EXPECT_EQ(farm::RedisAddress::parse("redis://cache/").port, 6379);
    auto message = [](const char* url) {
        try {
            farm::RedisAddress::parse(url);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("http://x:1"), "a Redis address is redis://HOST:PORT, not \"http://x:1\"");
    EXPECT_EQ(message("redis://x:99999"), "the port of \"redis://x:99999\" is not a number from 1 to 65535");
    EXPECT_EQ(message("redis://:1"), "\"redis://:1\" names no host");
}

}  // namespace
}  // namespace photon
