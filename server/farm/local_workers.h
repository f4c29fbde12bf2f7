// The render farm workers a photon-server runs itself (--workers N with --redis): FarmWorkers
// on threads of this process, taking items from the farm as any photon-worker does, so a
// coordinator's machine renders too and one machine with Redis is a farm of one.
#pragma once
#include <atomic>
#include <filesystem>
#include <memory>
#include <thread>
#include <vector>
#include "farm_worker.h"

namespace photon::farm {

class LocalWorkers {
public:
    // Connects `count` workers named HOST-PID-server-1 .. (throws RedisError if Redis cannot
    // be reached) and starts them; each unpacks scenes under scratch/<its name>.
    LocalWorkers(const RedisAddress& address, int count, const std::filesystem::path& scratch);
    ~LocalWorkers();  // stops them: an item in flight is finished first
    LocalWorkers(const LocalWorkers&) = delete;
    LocalWorkers& operator=(const LocalWorkers&) = delete;

private:
    std::filesystem::path scratch_;
    std::atomic<bool> stop_{false};
    std::vector<std::unique_ptr<FarmWorker>> workers_;
    std::vector<std::thread> threads_;
};

}  // namespace photon::farm
