// A render farm worker: takes work items from the work stream's consumer group (a job's
// batch of independent passes, or a whole job), renders them through the engine's face and
// publishes the batch's pass sums (or the job's passes, checkpoints and end) on the result
// stream, then acknowledges the item. Items another worker
// took and left pending longer than `claimAfter` (it died or hangs) are claimed first
// (XAUTOCLAIM). A job's cancellation mark stops its batch between passes and drops its
// items. Alive, it keeps a heartbeat hash (farm_keys.h) that expires when it stops.
#pragma once
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include "item_watch.h"
#include "redis_client.h"
#include "stream_entries.h"

namespace photon::farm {

// HOST-PID: a name no other worker process has.
std::string defaultWorkerName();
// This machine's name, as heartbeats report it.
std::string hostName();

struct WorkerOptions {
    RedisAddress redis;
    std::string name;                 // unique among the farm's workers
    int threads = 0;                  // rendering threads (reported; the process sets them)
    std::chrono::milliseconds claimAfter{30000};  // an item pending this long is taken over
    std::chrono::milliseconds block{1000};        // how long one read waits for new work
    std::filesystem::path scratch;    // where job scenes are unpacked (one folder per job)
};

class FarmWorker {
public:
    explicit FarmWorker(WorkerOptions options);
    ~FarmWorker();

    // Takes at most one item, a stale one first, and renders it; false if none came within
    // the block time.
    bool step();
    // Steps until `stop` is set.
    void run(const std::atomic<bool>& stop);

    // Read from other threads while the worker runs.
    struct Counters {
        std::atomic<int64_t> batches{0}, passes{0};  // items (batches, whole jobs) and passes rendered
        std::atomic<int64_t> claimed{0};             // items taken over from another worker
        std::atomic<int64_t> dropped{0};             // items of cancelled or deleted jobs
        std::atomic<int64_t> cancelled{0};           // batches stopped by a cancellation
    };
    const Counters& counters() const { return counters_; }

private:
    struct Job;
    void heartbeat(const std::string& item);
    std::chrono::milliseconds heartbeatTtl() const;
    void process(const StreamEntry& entry);
    // Each renders its item and publishes what it made; false if the job was gone.
    bool renderBatch(const StreamEntry& entry);
    bool renderJob(const StreamEntry& entry);
    WatchedItem watched(const StreamEntry& entry) const;
    Job* jobFor(const std::string& id);

    WorkerOptions options_;
    RedisClient redis_;
    Counters counters_;
    std::unique_ptr<Job> job_;  // the last job's scene, built: batches of one job follow each other
    double passesPerSecond_ = 0;
};

}  // namespace photon::farm
