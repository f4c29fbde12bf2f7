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
    int workers = 1;  // 0: accept and store jobs but render none (maintenance, tests)
    // A running job's state is saved this often (and when the server stops), so that a
    // crash or restart resumes it from there rather than from pass 0.
    double checkpointSeconds = 10;
    Limits limits;
};

class JobService {
public:
    // Loads every stored job; jobs that were queued or running are queued again.
    explicit JobService(const ServiceConfig& config);
    ~JobService();

    // A fresh staging area for an upload; hand it back to submit().
    std::unique_ptr<StagedUpload> newUpload() const;
    JobRecord submit(StagedUpload& upload, const SubmitOptions& options);

    JobRecord get(const std::string& id) const;
    JobTable::Page list(std::optional<JobStatus> status, size_t limit, size_t offset) const;
    struct CancelResult {
        JobRecord job;
        bool pending = false;  // running: the render stops at its next check
    };
    CancelResult cancel(const std::string& id);
    void remove(const std::string& id);
    // The latest image; nullopt while no pass has finished (or none was kept).
    std::optional<EncodedImage> image(const std::string& id, ImageFormat format);

    EventHub& events() { return hub_; }
    Metrics& metrics() { return metrics_; }
    const Limits& limits() const { return limits_; }
    std::map<JobStatus, int> jobCounts() const { return table_.countByStatus(); }

    // Ends every event stream (so the HTTP server can stop), then stops the workers;
    // renders in flight are interrupted and resume on the next start.
    void shutdown();

private:
    void restore();
    std::string unusedId() const;

    Limits limits_;
    JobFolders folders_;
    JobStore store_;
    JobTable table_;
    JobQueue queue_;
    ImageCache images_;
    EventHub hub_;
    Metrics metrics_;
    JobRunner runner_;
    std::unique_ptr<WorkerPool> workers_;
};

}  // namespace photon::server
