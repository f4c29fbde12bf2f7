// Renders one job from start to finish on the calling (worker) thread: loads the stored
// scene with the stored settings, runs the engine pass by pass, publishes every pass
// (image cache, job table, event hub, metrics) and records the outcome.
#pragma once
#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include "event_hub.h"
#include "image_cache.h"
#include "job_folders.h"
#include "job_store.h"
#include "job_table.h"
#include "metrics.h"
#include "progress_history.h"

namespace photon {
class PendingImage;
class Renderer;
struct RenderProgress;
}  // namespace photon

namespace photon::farm {
class FarmDispatcher;
struct FarmScene;
}  // namespace photon::farm

namespace photon::server {

// With a render farm (photon-server --redis), every job is rendered by the farm's workers:
// one whose passes are independent (render.radius_schedule "global") in batches of
// `batchPasses` passes, merged here in pass order; any other whole, by one worker at a time,
// which reports its passes and checkpoints here.
struct FarmUse {
    farm::FarmDispatcher* farm = nullptr;  // none: every job renders here
    int batchPasses = 4;
    double previewSeconds = 1;  // a whole job's image comes at most this often
};

class JobRunner {
public:
    JobRunner(JobTable& table, JobStore& store, const JobFolders& folders, ImageCache& images, EventHub& hub,
              Metrics& metrics, double checkpointSeconds, FarmUse farm = {})
        : table_(table), store_(store), folders_(folders), images_(images), hub_(hub), metrics_(metrics),
          checkpointSeconds_(checkpointSeconds), farm_(farm) {}

    // Does nothing if the job is no longer queued. Never throws.
    void run(const std::string& id);

private:
    enum class Ending { Completed, Cancelled, Paused, Interrupted };
    Ending render(const JobTable::Started& started);
    Ending renderOnFarm(const JobTable::Started& started, Renderer& renderer, double timeLimit);
    Ending renderWholeOnFarm(const JobTable::Started& started, const Renderer& renderer);
    farm::FarmScene farmScene(const JobTable::Started& started) const;
    // What a stop without completion means: cancelled, paused or the server stopping (the
    // state kept in the checkpoint for the last two).
    Ending stopped(const std::string& id, const Renderer& renderer);
    void onPass(const std::string& id, const JobSettings& settings, const Renderer& renderer,
                const RenderProgress& progress, double& elapsedBefore);
    // The same for a pass rendered elsewhere, its image given.
    void onPass(const std::string& id, const JobSettings& settings, std::shared_ptr<const PendingImage> image,
                const RenderProgress& progress, double& elapsedBefore);
    void finish(const std::string& id, JobStatus status, const std::string& error);
    void pause(const std::string& id);
    void writeImages(const std::string& id);
    void saveCheckpoint(const std::string& id, const Renderer& renderer);
    void resumeFromCheckpoint(const std::string& id, Renderer& renderer);

    // What a render keeps of its passes besides the latest image: its progress history,
    // saved at most once a second and when the render stops, and the earlier passes kept as
    // images (the first pass at or after each power of two: 1, 2, 4, 8, ...).
    struct PassLog {
        ProgressHistory history;
        std::chrono::steady_clock::time_point saved;
    };
    // Also gives `progress` the render's figures so far (MethodFigures), `pass` included.
    void recordPass(const std::string& id, const JobSettings& settings, const PendingImage& image,
                    JobProgress& progress, const PassStats& pass);
    void saveHistory(const std::string& id);  // and forgets the render's log

    JobTable& table_;
    JobStore& store_;
    const JobFolders& folders_;
    ImageCache& images_;
    EventHub& hub_;
    Metrics& metrics_;
    double checkpointSeconds_;
    FarmUse farm_;
    std::mutex logsMutex_;
    std::map<std::string, PassLog> logs_;  // of the renders in progress
};

}  // namespace photon::server
