// photon-worker: one machine's share of the render farm (docs/scale-out.md). Takes work
// items from Redis (batches of independent passes, or whole jobs), renders them with the
// engine and sends back what they made,
// until SIGINT or SIGTERM, after which it finishes nothing more: an item it was rendering
// stays pending and another worker claims it.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <photon/threads.h>
#include <thread>
#include "server/farm/farm_worker.h"

namespace {

std::atomic<bool> stopRequested{false};

void requestStop(int) { stopRequested.store(true); }

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli("Renders jobs and batches of passes for a photon-server started with --redis.", "photon-worker");
    std::string redis;
    photon::farm::WorkerOptions options;
    options.name = photon::farm::defaultWorkerName();
    double claimAfter = 30;
    cli.add_option("--redis", redis, "the farm's Redis, redis://HOST:PORT")->required();
    cli.add_option("--threads", options.threads, "rendering threads (default: one per core)")->check(CLI::Range(1, 4096));
    cli.add_option("--name", options.name, "this worker's name in the farm (default: HOST-PID)");
    cli.add_option("--claim-after", claimAfter, "seconds after which another worker's unfinished item is taken over")
        ->check(CLI::Range(0.1, 86400.0));
    CLI11_PARSE(cli, argc, argv);
    try {
        options.redis = photon::farm::RedisAddress::parse(redis);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "photon-worker: --redis: %s\n", e.what());
        return 2;
    }
    options.claimAfter = std::chrono::milliseconds(static_cast<int64_t>(claimAfter * 1000));
    options.scratch = std::filesystem::temp_directory_path() / ("photon-worker-" + options.name);
    std::optional<photon::ThreadLimit> limit;
    if (options.threads > 0) limit.emplace(size_t(options.threads));
    else options.threads = int(std::thread::hardware_concurrency());
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
    try {
        photon::farm::FarmWorker worker(options);
        std::printf("photon-worker %s: rendering for %s\n", options.name.c_str(), options.redis.url().c_str());
        std::fflush(stdout);
        worker.run(stopRequested);
        std::filesystem::remove_all(options.scratch);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photon-worker: %s\n", e.what());
        return 1;
    }
    return 0;
}
