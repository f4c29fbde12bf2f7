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

// The batches of `passes` passes from pass `firstPass` on, `batchPasses` each (the last may
// be shorter).
struct BatchPlan {
    int64_t passes = 0;
    int batchPasses = 1;
    int64_t firstPass = 0;
    int64_t batches() const { return (passes + batchPasses - 1) / batchPasses; }
    int64_t first(int64_t batch) const { return firstPass + batch * batchPasses; }
    int count(int64_t batch) const { return int(std::min<int64_t>(batchPasses, firstPass + passes - first(batch))); }
};

// A worker as its heartbeat describes it.
struct WorkerInfo {
    std::string name, host, item;  // item: JOB/BATCH being rendered, or empty
    int threads = 0;
    double passesPerSecond = 0;
    int64_t batches = 0, claimed = 0;
};

class FarmCoordinator {
public:
    FarmCoordinator(const RedisAddress& address, std::string name = "coordinator");

    // Stores the job's scene and adds a work item for each batch not in `merged`. Items and
    // results of an earlier submission of the job (before a restart) are dropped: each
    // submission is a round of its own, numbered by Redis.
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
        int64_t stale = 0;        // of an earlier round of their job
        int64_t batches = 0;      // handed on
        double batchSeconds = 0;  // their latencies summed, from submission to result
    };
    const Counters& counters() const { return counters_; }
    // Work items waiting or being rendered.
    int64_t queueDepth();
    // Makes the consumer groups if Redis has none (started without them, or restarted
    // without its data).
    void ensureGroups();
    // Workers whose heartbeat has not expired.
    std::vector<WorkerInfo> workers();

private:
    void dropQueuedItems(const std::string& job);

    RedisClient redis_;
    std::string name_;
    struct Submitted {
        std::string round;
        std::set<int64_t> handedOn;
        std::chrono::steady_clock::time_point at;  // when its items went out
    };
    std::map<std::string, Submitted> jobs_;
    Counters counters_;
};

}  // namespace photon::farm
