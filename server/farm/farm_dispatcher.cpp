#include "farm_dispatcher.h"
#include <spdlog/spdlog.h>
#include "farm_keys.h"

namespace photon::farm {

std::optional<FarmCoordinator::Result> FarmDispatcher::Results::next(std::chrono::milliseconds wait) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!ready_.wait_for(lock, wait, [&] { return !queue_.empty(); })) return std::nullopt;
    FarmCoordinator::Result r = std::move(queue_.front());
    queue_.pop_front();
    return r;
}

void FarmDispatcher::Results::push(FarmCoordinator::Result&& r) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.push_back(std::move(r));
    }
    ready_.notify_one();
}

FarmDispatcher::FarmDispatcher(const RedisAddress& address, std::string coordinatorName)
    : coordinator_(address, std::move(coordinatorName)), reader_([this] { readResults(); }) {}

FarmDispatcher::~FarmDispatcher() {
    stopping_.store(true);
    reader_.join();
}

// Reads in short waits, so that a runner starting or stopping a job waits at most that long
// for the coordinator's connection.
void FarmDispatcher::readResults() {
    while (!stopping_.load()) {
        try {
            std::lock_guard<std::mutex> lock(mutex_);
            coordinator_.collect(std::chrono::milliseconds(50), [&](FarmCoordinator::Result&& r) {
                auto job = jobs_.find(r.job);
                if (job != jobs_.end()) job->second->push(std::move(r));
            });
        } catch (const std::exception& e) {
            // Redis away: wait, then read again (the client reconnects; the result group is
            // made again if Redis lost it).
            spdlog::error("render farm: {}", e.what());
            std::this_thread::sleep_for(std::chrono::seconds(1));
            try {
                std::lock_guard<std::mutex> lock(mutex_);
                coordinator_.ensureGroups();
            } catch (const std::exception&) {
            }
        }
        std::this_thread::yield();
    }
}

// Called with the lock held, after the submission.
std::shared_ptr<FarmDispatcher::Results> FarmDispatcher::follow(const std::string& job) {
    auto results = std::make_shared<Results>();
    jobs_[job] = results;
    return results;
}

std::shared_ptr<FarmDispatcher::Results> FarmDispatcher::start(const std::string& job, const FarmScene& scene,
                                                                 const BatchPlan& plan) {
    std::lock_guard<std::mutex> lock(mutex_);
    coordinator_.submit(job, scene, plan);
    return follow(job);
}

std::shared_ptr<FarmDispatcher::Results> FarmDispatcher::startJob(const std::string& job, const FarmScene& scene,
                                                                    const WholeJobPlan& plan,
                                                                    const std::optional<std::string>& checkpoint) {
    std::lock_guard<std::mutex> lock(mutex_);
    coordinator_.submitJob(job, scene, plan, checkpoint);
    return follow(job);
}

void FarmDispatcher::stop(const std::string& job) {
    std::lock_guard<std::mutex> lock(mutex_);
    jobs_.erase(job);
    coordinator_.forget(job);
}

FarmCoordinator::Counters FarmDispatcher::counters() {
    std::lock_guard<std::mutex> lock(mutex_);
    return coordinator_.counters();
}

int64_t FarmDispatcher::queueDepth() {
    std::lock_guard<std::mutex> lock(mutex_);
    return coordinator_.queueDepth();
}

std::vector<WorkerInfo> FarmDispatcher::workers() {
    std::lock_guard<std::mutex> lock(mutex_);
    return coordinator_.workers();
}

}  // namespace photon::farm
