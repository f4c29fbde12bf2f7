// The coordinator's side of the render farm: publishes a job's scene and its batches of
// independent passes as work items, and collects the workers' results, handing each
// (job, batch) on exactly once however many times workers delivered it (a slow worker's
// item re-delivered to another). What it hands on is merged by the caller, which keeps the
// merged batches in its checkpoint: on a restart it submits again only those not merged.
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <photon/pass_sums.h>
#include "farm_scene.h"
#include "redis_client.h"

namespace photon::farm {

// The batches of a job of `passes` passes, `batchPasses` each (the last may be shorter).
struct BatchPlan {
    int64_t passes = 0;
    int batchPasses = 1;
    int64_t batches() const { return (passes + batchPasses - 1) / batchPasses; }
    int64_t first(int64_t batch) const { return batch * batchPasses; }
    int count(int64_t batch) const { return int(std::min<int64_t>(batchPasses, passes - first(batch))); }
};

class FarmCoordinator {
public:
    FarmCoordinator(const RedisAddress& address, std::string name = "coordinator");

    // Stores the job's scene and adds a work item for each batch not in `merged`.
    void submit(const std::string& job, const FarmScene& scene, const BatchPlan& plan,
                const std::set<int64_t>& merged = {});

    // A result: the batch's sums, or the error that made a worker give it up.
    struct Result {
        std::string job, worker, error;
        int64_t batch = 0;
        PassSums sums;
    };
    // Waits up to `wait` for results and hands each new (job, batch) to onResult once; a
    // result of a job not submitted here (or forgotten) is dropped. Returns how many went.
    size_t collect(std::chrono::milliseconds wait, const std::function<void(Result&&)>& onResult);

    // Marks the job cancelled: workers stop its batch and drop its items.
    void cancel(const std::string& job);
    // Cancels it and removes its scene and its items still queued.
    void forget(const std::string& job);

    struct Counters {
        int64_t results = 0;      // results read
        int64_t duplicates = 0;   // of batches handed on before (re-deliveries)
    };
    const Counters& counters() const { return counters_; }
    // Work items waiting or being rendered.
    int64_t queueDepth();

private:
    RedisClient redis_;
    std::string name_;
    std::map<std::string, std::set<int64_t>> handedOn_;  // per submitted job
    Counters counters_;
};

}  // namespace photon::farm
