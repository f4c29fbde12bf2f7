// photon-farm-bench: the render farm's throughput and the coordinator's merge cost. Starts
// Debian's redis-server on a free loopback port, then for each worker count N starts N
// photon-worker processes of one thread each, pinned to cores round-robin, and has an
// in-process FarmCoordinator hand them one job of independent passes in batches that take
// about --batch-seconds each; the coordinator merges every batch as photon-server does.
// Prints passes per second, the efficiency against N times one worker's rate (and per core
// when N exceeds the cores), and the merge cost per batch against the batch's render time.
// Speed targets live here, never in timed tests (docs/scale-out.md has the figures).
//
//   photon-farm-bench [--scene FILE] [--workers 1,2,4] [--batch-seconds S] [--batches-per-worker K]
#include <sched.h>
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <thread>
#include <photon/render.h>
#include <photon/threads.h>
#include "redis_process.h"
#include "server/farm/farm_coordinator.h"
#include "server/farm/farm_scene.h"

namespace {

using namespace photon;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Options {
    std::string scene = std::string(PHOTON_SOURCE_DIR) + "/scenes/cornell-box.json";
    std::vector<int> workers{1, 2, 4};
    double batchSeconds = 1.0;
    int batchesPerWorker = 6;
};

std::vector<SettingOverride> globalSchedule(int64_t passes) {
    return {{"render.radius_schedule", "global"}, {"render.passes", std::to_string(passes)}};
}

// One thread's seconds per pass, from a few passes in this process.
double secondsPerPass(const Options& o) {
    ThreadLimit one(1);
    Renderer renderer(SceneFile::read(o.scene, globalSchedule(8)));
    CancelToken never;
    renderer.renderPasses(0, 1, never);  // the first pass builds what later ones reuse
    const auto start = Clock::now();
    renderer.renderPasses(1, 3, never);
    return secondsSince(start) / 3;
}

void pin(pid_t pid, int core) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(core, &set);
    sched_setaffinity(pid, sizeof set, &set);
}

struct Run {
    double passesPerSecond = 0, mergeSecondsPerBatch = 0;
};

Run runFarm(const Options& o, const test::RedisProcess& redis, int workers, int batchPasses, const std::string& job) {
    const int cores = int(std::thread::hardware_concurrency());
    std::vector<std::unique_ptr<test::WorkerProcess>> processes;
    for (int i = 0; i < workers; ++i) {
        processes.push_back(std::make_unique<test::WorkerProcess>(redis.address(), job + "-w" + std::to_string(i),
                                                                  PHOTON_WORKER_BINARY));
        pin(processes.back()->pid(), i % cores);
    }
    farm::FarmCoordinator coordinator(redis.address(), "bench");
    while (int(coordinator.workers().size()) < workers) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const int64_t passes = int64_t(workers) * o.batchesPerWorker * batchPasses;
    const std::filesystem::path file(o.scene);
    farm::FarmScene scene = farm::FarmScene::fromFolder(file.parent_path(), file.filename().string(), globalSchedule(passes));
    Renderer merged(SceneFile::read(o.scene, globalSchedule(passes)));
    const auto start = Clock::now();
    coordinator.submit(job, scene, farm::BatchPlan{passes, batchPasses, 0});
    int64_t got = 0;
    double mergeSeconds = 0;
    int batches = 0;
    while (got < passes)
        coordinator.collect(std::chrono::milliseconds(100), [&](farm::FarmCoordinator::Result&& r) {
            if (!r.error.empty()) throw std::runtime_error(r.error);
            const auto mergeStart = Clock::now();
            merged.addPasses(r.sums);
            mergeSeconds += secondsSince(mergeStart);
            got += r.sums.count;
            ++batches;
        });
    Run run;
    run.passesPerSecond = double(passes) / secondsSince(start);
    // The decode happens inside collect: timed here on one batch's bytes, as the server gets them.
    CancelToken never;
    Renderer one(SceneFile::read(o.scene, globalSchedule(passes)));
    const std::string bytes = one.renderPasses(0, 1, never)->encode();
    const auto decodeStart = Clock::now();
    for (int i = 0; i < 5; ++i) (void)PassSums::decode(bytes);
    run.mergeSecondsPerBatch = mergeSeconds / batches + secondsSince(decodeStart) / 5;
    coordinator.forget(job);
    return run;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("The render farm's throughput with 1, 2, 4 worker processes, and the merge cost.", "photon-farm-bench");
    Options o;
    app.add_option("--scene", o.scene, "the scene (rendered with the global radius schedule)")->capture_default_str();
    app.add_option("--workers", o.workers, "worker counts to time")->delimiter(',')->capture_default_str();
    app.add_option("--batch-seconds", o.batchSeconds, "about how long one batch takes")->capture_default_str();
    app.add_option("--batches-per-worker", o.batchesPerWorker, "batches per worker in each run")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try {
        const double perPass = secondsPerPass(o);
        const int batchPasses = std::max(1, int(std::ceil(o.batchSeconds / perPass)));
        const int cores = int(std::thread::hardware_concurrency());
        std::printf("scene %s, %d cores; one thread renders a pass in %.3f s in process: %.2f passes/s\n",
                    o.scene.c_str(), cores, perPass, 1 / perPass);
        std::printf("batches of %d passes (%.2f s), %d batches per worker, workers of 1 thread pinned round-robin\n\n",
                    batchPasses, batchPasses * perPass, o.batchesPerWorker);
        std::printf("| workers | passes/s | x one worker | efficiency | per core used | merge per batch | of a batch's render |\n");
        std::printf("|---|---|---|---|---|---|---|\n");
        test::RedisProcess redis;
        double single = 0;
        for (int n : o.workers) {
            const Run r = runFarm(o, redis, n, batchPasses, "bench-" + std::to_string(n));
            if (single == 0) single = r.passesPerSecond / double(o.workers.front());
            const int used = std::min(n, cores);
            std::printf("| %d | %.2f | %.2f | %.0f%% | %.0f%% | %.2f ms | %.2f%% |\n", n, r.passesPerSecond,
                        r.passesPerSecond / single, 100 * r.passesPerSecond / (n * single),
                        100 * r.passesPerSecond / (used * single), 1000 * r.mergeSecondsPerBatch,
                        100 * r.mergeSecondsPerBatch / (batchPasses * perPass));
            std::fflush(stdout);
        }
        std::printf("\n(one worker against one thread in process: %.0f%%)\n", 100 * single * perPass);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-farm-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
