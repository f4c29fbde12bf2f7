// The render service as the API layer sees it: submit, inspect, cancel and delete jobs,
// fetch their images, follow their events. Owns persistence, the queue and the workers.
// Operations throw ServiceError for anything the client can correct.
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include "event_hub.h"
#include "farm/farm_dispatcher.h"
#include "farm/local_workers.h"
#include "progress_history.h"
#include "idempotency.h"
#include "image_cache.h"
#include "job_folders.h"
#include "job_queue.h"
#include "job_runner.h"
#include "job_store.h"
#include "job_table.h"
#include "service_limits.h"
#include "metrics.h"
#include "scene_intake.h"
#include "staged_upload.h"
#include "worker_pool.h"

namespace photon::server {

struct ServiceConfig {
    std::filesystem::path dataDir = "data";
    // Jobs rendered at once; 0: accept and store jobs but render none (maintenance, tests).
    // With a render farm: the farm workers this process runs itself (0: it renders nothing).
    int workers = 1;
    // A running job's state is saved this often (and when the server stops), so that a
    // crash or restart resumes it from there rather than from pass 0.
    double checkpointSeconds = 10;
    Limits limits;
    // The render farm (docs/scale-out.md): with a Redis address, jobs whose passes are
    // independent are rendered by photon-worker processes, `farmBatchPasses` passes an item.
    std::optional<farm::RedisAddress> redis;
    int farmBatchPasses = 4;
    int farmJobs = 16;  // jobs on the farm at once
};

// A submission as the API layer hands it over: the overrides, who sends it, and how to
// recognise a retry of it.
struct SubmitRequest {
    SubmitOptions options;
    std::string client;                         // the remote address
    std::optional<std::string> idempotencyKey;  // already checked with idempotencyKeyProblem
    std::string digest;                         // RequestDigest::hex() of the body and query
};

struct SubmitResult {
    JobRecord job;
    bool created = true;  // false: a retry, answered with the job its key first created
};

class JobService {
public:
    // Loads every stored job; jobs that were queued or running are queued again.
    explicit JobService(const ServiceConfig& config);
    ~JobService();

    // A fresh staging area for an upload; hand it back to submit(). Throws ServiceError
    // (StorageFull, Unavailable) when the data directory cannot be written.
    std::unique_ptr<StagedUpload> newUpload() const;
    // Validates and stores the job and queues it; or, for a key seen in the last 24 hours,
    // returns the job it created (a different request under that key: LimitExceeded).
    // Over the per-client or queue limits: TooManyRequests / Unavailable.
    SubmitResult submit(StagedUpload& upload, const SubmitRequest& request);

    JobRecord get(const std::string& id) const;
    JobTable::Page list(const JobFilter& filter, size_t limit, size_t offset) const;
    struct CancelResult {
        JobRecord job;
        bool pending = false;  // running: the render stops at its next check
    };
    CancelResult cancel(const std::string& id);
    // Pause: a queued job at once, a running one after its current pass (pending), keeping
    // its checkpoint and image. Resume: back in the queue, to go on from that pass.
    CancelResult pause(const std::string& id);
    JobRecord resume(const std::string& id);
    // A completed job rendered on for `morePasses` more passes from its checkpoint.
    JobRecord continueJob(const std::string& id, int64_t morePasses);
    // A queued job's place in the queue: Conflict once it has started.
    JobRecord setPriority(const std::string& id, int priority);
    // A new job with the scene and assets of job `id` and the given settings; options left
    // unset keep the original's (its name and labels too). Held to the same limits as a
    // submission.
    SubmitResult clone(const std::string& id, const SubmitOptions& overrides, const std::string& client);
    // The scene as submitted, and the name it is stored under (JobFolders::sceneFileNames).
    std::string scene(const std::string& id) const;
    std::string sceneFileName(const std::string& id) const;
    // The job's own log (job_log.h).
    std::string log(const std::string& id) const;
    void remove(const std::string& id);
    // The latest image; nullopt while no pass has finished (or none was kept).
    std::optional<EncodedImage> image(const std::string& id, ImageFormat format);
    // A kept earlier pass (JobRecord::keptPasses) as EXR; NotFound naming the kept passes if
    // `pass` is not one of them.
    EncodedImage keptPass(const std::string& id, int pass);
    // The job's progress over its passes (progress_history.h); NotFound for no such job.
    std::vector<ProgressPoint> progressHistory(const std::string& id);

    EventHub& events() { return hub_; }
    Metrics& metrics() { return metrics_; }
    const Limits& limits() const { return limits_; }
    std::map<JobStatus, int> jobCounts() const { return table_.countByStatus(); }
    // The render farm's figures; nullopt without one (or while Redis cannot be reached).
    std::optional<FarmFigures> farmFigures();

    // Ends every event stream (so the HTTP server can stop), then stops the workers;
    // renders in flight are interrupted and resume on the next start.
    void shutdown();

private:
    void restore();
    std::string unusedId() const;
    std::optional<JobRecord> replay(const std::string& key, const std::string& digest);
    void checkAdmission(const std::string& client, int64_t uploadBytes) const;
    void logAccepted(const JobRecord& job) const;

    Limits limits_;
    JobFolders folders_;
    JobStore store_;
    JobTable table_;
    JobQueue queue_;
    ImageCache images_;
    EventHub hub_;
    Metrics metrics_;
    std::unique_ptr<farm::FarmDispatcher> farm_;  // before runner_, which uses it
    JobRunner runner_;
    std::unique_ptr<WorkerPool> workers_;
    std::unique_ptr<farm::LocalWorkers> farmWorkers_;  // with a farm: the ones this process runs
    KeyLocks keyLocks_;
    std::mutex admission_;  // the limit checks and the insert they admit happen as one step
};

}  // namespace photon::server
