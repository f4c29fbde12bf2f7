// The coordinator's side of the render farm: publishes a job's scene and either its batches
// of independent passes or the whole job as work items, and collects the workers' results,
// handing each (job, batch) on exactly once however many times workers delivered it (a slow
// worker's item re-delivered to another); a whole job's reports are handed on as they come. What it hands on is merged by the caller, which keeps the
// merged batches in its checkpoint: on a restart it submits again only those not merged.
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <optional>
#include <photon/image.h>
#include <photon/pass_sums.h>
#include <photon/progress.h>
#include "farm_scene.h"
#include "redis_client.h"

namespace photon::farm {

// The batches of `passes` passes from pass `firstPass` on, `batchPasses` each (the last may
// be shorter). At most `ahead` of them are queued at a time, one more as each comes back, so
// a job of many passes keeps Redis small and one that ends early (a time limit, a cancel)
// leaves little to drop.
struct BatchPlan {
    int64_t passes = 0;
    int batchPasses = 1;
    int64_t firstPass = 0;
    int64_t ahead = 64;
    int64_t batches() const { return (passes + batchPasses - 1) / batchPasses; }
    int64_t first(int64_t batch) const { return firstPass + batch * batchPasses; }
    int count(int64_t batch) const { return int(std::min<int64_t>(batchPasses, firstPass + passes - first(batch))); }
};

// A job rendered whole by one worker at a time: how often it reports.
struct WholeJobPlan {
    double checkpointSeconds = 10;  // a checkpoint (kept in Redis for a worker taking over)
    double previewSeconds = 1;      // a pass's progress and image, at most this often
};

// A worker as its heartbeat describes it.
struct WorkerInfo {
    std::string name, host, item;  // item: JOB/BATCH being rendered, or empty
    int threads = 0;
    double passesPerSecond = 0;
    int64_t batches = 0, claimed = 0;
};

class FarmCoordinator {
    struct Submitted {
        std::string round;
        std::set<int64_t> handedOn;
        std::chrono::steady_clock::time_point at;  // when it was submitted
        BatchPlan plan;
        int64_t next = 0;  // the next batch to queue
        std::map<int64_t, std::chrono::steady_clock::time_point> queuedAt;  // batches out, when queued
    };

public:
    FarmCoordinator(const RedisAddress& address, std::string name = "coordinator");

    // Stores the job's scene and adds a work item for each batch not in `merged`. Items and
    // results of an earlier submission of the job (before a restart) are dropped: each
    // submission is a round of its own, numbered by Redis.
    void submit(const std::string& job, const FarmScene& scene, const BatchPlan& plan,
                const std::set<int64_t>& merged = {});

    // Puts the job on the farm whole, to resume from `checkpoint` (Renderer::saveCheckpoint's
    // bytes) if given. Earlier submissions of the job are dropped as for batches.
    void submitJob(const std::string& job, const FarmScene& scene, const WholeJobPlan& plan,
                   const std::optional<std::string>& checkpoint);

    // A result: a batch's sums, a whole job's pass (progress and raw image), checkpoint or
    // end, or the error that made a worker give the item up.
    struct Result {
        enum class Kind { Batch, Pass, Checkpoint, Done };
        Kind kind = Kind::Batch;
        std::string job, worker, error;
        int64_t batch = 0;
        PassSums sums;
        RenderProgress progress;  // Pass (Checkpoint and Done: only progress.pass)
        Image image;              // Pass: the render's raw image after it
        std::string checkpoint;   // Checkpoint: its bytes
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
        double batchSeconds = 0;  // their latencies summed, from queueing to result
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
    // Queues the job's next batch not handed on yet, if any.
    void queueNext(const std::string& job, Submitted& s);
    // Drops what an earlier submission of the job left, stores its scene and numbers the
    // new round, which becomes the job's current one.
    std::string beginRound(const std::string& job, const FarmScene& scene);
    void dropQueuedItems(const std::string& job);
    // Reads a result entry of a submitted job into `r`; false for a duplicate batch.
    bool readResult(const struct StreamEntry& e, Submitted& job, Result& r);

    RedisClient redis_;
    std::string name_;
    std::map<std::string, Submitted> jobs_;
    Counters counters_;
};

}  // namespace photon::farm
