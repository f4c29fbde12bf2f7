#include "local_workers.h"
#include <thread>

namespace photon::farm {

LocalWorkers::LocalWorkers(const RedisAddress& address, int count, const std::filesystem::path& scratch)
    : scratch_(scratch) {
    for (int i = 1; i <= count; ++i) {
        WorkerOptions options;
        options.redis = address;
        options.name = defaultWorkerName() + "-server-" + std::to_string(i);
        // The engine's threads are the process's: each worker's render shares them.
        options.threads = int(std::thread::hardware_concurrency());
        options.scratch = scratch / options.name;
        workers_.push_back(std::make_unique<FarmWorker>(options));
    }
    for (auto& worker : workers_) threads_.emplace_back([this, w = worker.get()] { w->run(stop_); });
}

LocalWorkers::~LocalWorkers() {
    stop_.store(true);
    for (std::thread& t : threads_) t.join();
    workers_.clear();
    std::error_code ec;
    std::filesystem::remove_all(scratch_, ec);  // unpacked scenes; the jobs keep theirs
}

}  // namespace photon::farm
