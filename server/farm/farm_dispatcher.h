// The render farm as the job service uses it: one coordinator for the whole process, one
// thread reading the result stream, and per job on the farm a queue its runner waits on.
// Jobs are started, cancelled and forgotten from the runners' threads.
#pragma once
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include "farm_coordinator.h"

namespace photon::farm {

class FarmDispatcher {
public:
    // Connects (throws RedisError if Redis cannot be reached) and starts reading results.
    FarmDispatcher(const RedisAddress& address, std::string coordinatorName);
    ~FarmDispatcher();

    // Puts the job's batches on the farm and returns the queue its results arrive in.
    class Results {
    public:
        // The next result, or nullopt after `wait`.
        std::optional<FarmCoordinator::Result> next(std::chrono::milliseconds wait);

    private:
        friend class FarmDispatcher;
        void push(FarmCoordinator::Result&& r);
        std::mutex mutex_;
        std::condition_variable ready_;
        std::deque<FarmCoordinator::Result> queue_;
    };
    std::shared_ptr<Results> start(const std::string& job, const FarmScene& scene, const BatchPlan& plan);
    // Puts the job on the farm whole (FarmCoordinator::submitJob).
    std::shared_ptr<Results> startJob(const std::string& job, const FarmScene& scene, const WholeJobPlan& plan,
                                      const std::optional<std::string>& checkpoint);
    // Stops the job's batches and drops its queued items; its results are no longer
    // delivered.
    void stop(const std::string& job);

    // For /metrics and the workers list.
    FarmCoordinator::Counters counters();
    int64_t queueDepth();
    // Workers whose heartbeat has not expired.
    std::vector<WorkerInfo> workers();

private:
    void readResults();
    std::shared_ptr<Results> follow(const std::string& job);

    std::mutex mutex_;  // guards coordinator_ and jobs_
    FarmCoordinator coordinator_;
    std::map<std::string, std::shared_ptr<Results>> jobs_;
    std::atomic<bool> stopping_{false};
    std::thread reader_;
};

}  // namespace photon::farm
