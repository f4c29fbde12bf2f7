#include "job_runner.h"
#include <chrono>
#include <cstdio>
#include <spdlog/spdlog.h>
#include <fstream>
#include <map>
#include <sstream>
#include <photon/image_io.h>
#include <photon/render.h>
#include "clock.h"
#include "farm/farm_dispatcher.h"
#include "image_metadata.h"
#include "kept_passes.h"
#include "job_log.h"
#include "scene_intake.h"

namespace photon::server {

namespace {

// A setting's number as a scene override's text, round-tripping exactly.
std::string exactDecimal(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

}  // namespace

void JobRunner::run(const std::string& id) {
    std::optional<JobTable::Started> started = table_.start(id, utcNowIso8601());
    if (!started) return;  // cancelled while it waited in the queue
    try {
        store_.update(started->job);
        hub_.publish(started->job, std::nullopt);
        Ending ending;
        try {
            ending = render(*started);
        } catch (...) {
            saveHistory(id);
            throw;
        }
        saveHistory(id);
        // A stop without a client's cancel is the server shutting down: the store still says
        // "running", so the next start queues the job again.
        if (ending == Ending::Interrupted) {
            appendJobLog(folders_.logFile(id), "interrupted by the server stopping after pass " +
                                                   std::to_string(table_.find(id)->progress.pass) +
                                                   "; it resumes from there on the next start");
            return;
        }
        if (ending == Ending::Paused) return pause(id);
        finish(id, ending == Ending::Completed ? JobStatus::Completed : JobStatus::Cancelled, "");
    } catch (const std::exception& e) {
        try {
            finish(id, JobStatus::Failed, e.what());
        } catch (const std::exception& again) {
            spdlog::error("job {}: {} (while recording: {})", id, again.what(), e.what());
        }
    }
}

JobRunner::Ending JobRunner::render(const JobTable::Started& started) {
    const std::string& id = started.job.id;
    SceneFile scene = readJobScene(folders_.sceneFile(id), started.job.settings);
    const double timeLimit = scene.render().timeLimitSeconds;
    Renderer renderer(std::move(scene));
    resumeFromCheckpoint(id, renderer);
    int resumedAt = renderer.progress().pass;
    appendJobLog(folders_.logFile(id), resumedAt > 0 ? "resumed from its checkpoint after pass " + std::to_string(resumedAt)
                                                     : "started");
    if (farm_.farm)
        return renderer.independentPasses() ? renderOnFarm(started, renderer, timeLimit) : renderWholeOnFarm(started, renderer);
    double elapsedBefore = renderer.progress().elapsedSeconds;
    auto lastCheckpoint = std::chrono::steady_clock::now();
    RenderOutcome outcome = renderer.run(*started.cancel, [&](const RenderProgress& p) {
        onPass(id, started.job.settings, renderer, p, elapsedBefore);
        auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - lastCheckpoint).count() >= checkpointSeconds_) {
            saveCheckpoint(id, renderer);
            lastCheckpoint = now;
        }
    });
    if (outcome != RenderOutcome::Cancelled) {  // pass count or time limit reached
        saveCheckpoint(id, renderer);            // kept: more passes can follow
        return Ending::Completed;
    }
    return stopped(id, renderer);
}

JobRunner::Ending JobRunner::stopped(const std::string& id, const Renderer& renderer) {
    if (table_.cancelRequested(id)) return Ending::Cancelled;
    // Paused, or the server is stopping: keep the state after the last finished pass.
    saveCheckpoint(id, renderer);
    return table_.pauseRequested(id) ? Ending::Paused : Ending::Interrupted;
}

// The job's folder as the farm carries it: the scene and what it reads, none of the service's
// own files, with the job's settings on top.
farm::FarmScene JobRunner::farmScene(const JobTable::Started& started) const {
    const std::string& id = started.job.id;
    const JobSettings& settings = started.job.settings;
    const std::filesystem::path sceneFile = folders_.sceneFile(id);
    farm::FarmScene scene = farm::FarmScene::fromFolder(
        folders_.jobDir(id), sceneFile.filename().string(),
        {{"render.passes", std::to_string(settings.passes)},
         {"render.photons_per_pass", std::to_string(settings.photonsPerPass)},
         {"render.seed", std::to_string(settings.seed)},
         {"render.target_error", exactDecimal(settings.targetError)}},
        [&](const std::filesystem::path& relative) {
            const std::string name = relative.generic_string();
            return name == sceneFile.filename().string() || !JobFolders::isServiceFile(name);
        });
    scene.camera = settings.camera;
    scene.lenient = settings.lenient;
    return scene;
}

// The farm renders batches of passes after the ones the checkpoint holds; they are merged in
// pass order (a batch that arrives early waits in memory), so the checkpoint's pass count
// says exactly which are merged and a restart asks the farm for the rest only. The image
// is the one this process would render, bit for bit (docs/scale-out.md).
JobRunner::Ending JobRunner::renderOnFarm(const JobTable::Started& started, Renderer& renderer, double timeLimit) {
    const std::string& id = started.job.id;
    const JobSettings& settings = started.job.settings;
    const int64_t total = renderer.progress().totalPasses;
    int64_t merged = renderer.progress().pass;
    const int64_t mergedAtStart = merged;
    const farm::FarmScene scene = farmScene(started);
    auto results = farm_.farm->start(id, scene, farm::BatchPlan{total - merged, farm_.batchPasses, merged});
    appendJobLog(folders_.logFile(id), "on the render farm from pass " + std::to_string(merged) + ", " +
                                           std::to_string(farm_.batchPasses) + " passes a batch");
    std::map<int64_t, PassSums> early;  // batches that came before the passes before them
    const double elapsedBefore = started.job.progress.elapsedSeconds;
    double elapsedAtLastPass = elapsedBefore;
    const auto start = std::chrono::steady_clock::now();
    auto lastCheckpoint = start;
    // The time limit (or the target error) ends the render after the batch that crosses it,
    // as a local render ends after the pass that crosses it; the batches in flight are dropped.
    bool timeUp = false;
    while (merged < total && !timeUp) {
        if (started.cancel->cancelled()) {
            farm_.farm->stop(id);
            return stopped(id, renderer);
        }
        std::optional<farm::FarmCoordinator::Result> r = results->next(std::chrono::milliseconds(200));
        if (!r) continue;
        if (!r->error.empty()) {
            farm_.farm->stop(id);
            throw std::runtime_error("worker " + r->worker + ": " + r->error);
        }
        if (r->sums.first < merged) continue;  // passes merged already
        early.emplace(r->sums.first, std::move(r->sums));
        while (!early.empty() && early.begin()->first == merged && !timeUp) {
            const int64_t count = early.begin()->second.count;
            renderer.addPasses(early.begin()->second);
            merged += count;
            early.erase(early.begin());
            RenderProgress p = renderer.progress();
            p.elapsedSeconds = elapsedBefore + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            // At the rate of the batches merged since this start.
            const double perPass = (p.elapsedSeconds - elapsedBefore) / double(merged - mergedAtStart);
            p.etaSeconds = perPass * double(total - merged);
            if (p.passesToTarget) p.etaSeconds = std::min(p.etaSeconds, perPass * *p.passesToTarget);
            p.lastPass = PassStats{};
            p.lastPass.photons = settings.photonsPerPass * count;
            double before = elapsedAtLastPass;
            onPass(id, settings, renderer, p, before);
            elapsedAtLastPass = p.elapsedSeconds;
            timeUp = (timeLimit > 0 && p.elapsedSeconds >= timeLimit) || renderer.targetErrorReached();
            const auto now = std::chrono::steady_clock::now();
            if (std::chrono::duration<double>(now - lastCheckpoint).count() >= checkpointSeconds_) {
                saveCheckpoint(id, renderer);
                lastCheckpoint = now;
            }
        }
    }
    farm_.farm->stop(id);  // its scene and marks go; nothing of it is left to render
    saveCheckpoint(id, renderer);
    return Ending::Completed;
}

// One worker at a time renders the job, from the checkpoint this process holds; its passes
// (at most one a preview interval, the last always) and checkpoints come back here. A worker
// taking over a dead one's item resumes from the last checkpoint in Redis, so passes come
// again: only passes after the last shown are shown. Pause and the server stopping keep the
// last checkpoint received (up to --checkpoint-seconds of passes are rendered again).
JobRunner::Ending JobRunner::renderWholeOnFarm(const JobTable::Started& started, const Renderer& renderer) {
    const std::string& id = started.job.id;
    std::optional<std::string> checkpoint = readWholeFile(folders_.checkpointFile(id));
    auto results = farm_.farm->startJob(id, farmScene(started), farm::WholeJobPlan{checkpointSeconds_, farm_.previewSeconds},
                                        checkpoint);
    int shown = renderer.progress().pass, checkpointed = shown;
    appendJobLog(folders_.logFile(id), "on the render farm as a whole job from pass " + std::to_string(shown));
    double elapsedBefore = started.job.progress.elapsedSeconds;
    while (true) {
        if (started.cancel->cancelled()) {
            farm_.farm->stop(id);
            if (table_.cancelRequested(id)) return Ending::Cancelled;
            return table_.pauseRequested(id) ? Ending::Paused : Ending::Interrupted;
        }
        std::optional<farm::FarmCoordinator::Result> r = results->next(std::chrono::milliseconds(200));
        if (!r) continue;
        if (!r->error.empty()) {
            farm_.farm->stop(id);
            throw std::runtime_error("worker " + r->worker + ": " + r->error);
        }
        using Kind = farm::FarmCoordinator::Result::Kind;
        if (r->kind == Kind::Pass && r->progress.pass > shown) {
            shown = r->progress.pass;
            onPass(id, started.job.settings, renderer.pendingLayersOf(std::move(r->image)), r->progress, elapsedBefore);
        } else if (r->kind == Kind::Checkpoint && r->progress.pass > checkpointed) {
            checkpointed = r->progress.pass;
            writeFileAtomically(folders_.checkpointFile(id), r->checkpoint);
        } else if (r->kind == Kind::Done) {
            farm_.farm->stop(id);
            return Ending::Completed;
        }
    }
}

void JobRunner::saveCheckpoint(const std::string& id, const Renderer& renderer) {
    std::ostringstream bytes;
    renderer.saveCheckpoint(bytes);
    writeFileAtomically(folders_.checkpointFile(id), bytes.str());  // a crash leaves the old one whole
}

void JobRunner::resumeFromCheckpoint(const std::string& id, Renderer& renderer) {
    const std::filesystem::path file = folders_.checkpointFile(id);
    std::ifstream in(file, std::ios::binary);
    if (!in) return;
    try {
        renderer.restoreCheckpoint(in);
    } catch (const CheckpointError& e) {
        // Unusable (another version, a damaged file): render from the start instead.
        spdlog::warn("job {}: {}; starting over", id, e.what());
        appendJobLog(folders_.logFile(id), "checkpoint discarded (" + std::string(e.what()) + "); starting over");
        std::error_code ec;
        std::filesystem::remove(file, ec);
    }
}

void JobRunner::onPass(const std::string& id, const JobSettings& settings, const Renderer& renderer,
                       const RenderProgress& p, double& elapsedBefore) {
    // Between passes the snapshot is exactly the image after pass p.pass (denoised, with
    // its raw and guide layers, when the scene asks for it: the engine decides, and does
    // it when the image is first encoded).
    onPass(id, settings, renderer.pendingLayers(), p, elapsedBefore);
}

void JobRunner::onPass(const std::string& id, const JobSettings& settings, std::shared_ptr<const PendingImage> image,
                       const RenderProgress& p, double& elapsedBefore) {
    // The image's files say how far the render had got then.
    JobProgress progress{p.pass, p.photonsTraced, p.meanRadius, p.elapsedSeconds, p.etaSeconds, p.relativeError, {}};
    recordPass(id, settings, *image, progress, p.lastPass);
    ImageMetadata metadata = passMetadata(settings, progress, image->exposure());
    images_.store(id, p.pass, std::move(image), std::move(metadata));
    hub_.publish(table_.setProgress(id, progress), EventType::Progress);
    metrics_.addPass(p.lastPass.photons, p.elapsedSeconds - elapsedBefore);
    elapsedBefore = p.elapsedSeconds;
}

void JobRunner::recordPass(const std::string& id, const JobSettings& settings, const PendingImage& image,
                           JobProgress& progress, const PassStats& pass) {
    // Both are for looking back at the render, not the render: one that cannot be written
    // (a full disk) is left out with a warning, and the checkpoint decides whether the job
    // can go on.
    if (isKeptPass(progress.pass, table_.find(id)->keptPasses)) {
        // Encoded once here (with the denoiser's layers, when it runs): a few passes of a
        // whole render, 1, 2, 4, ..., so a client can compare how the image settled.
        try {
            const std::filesystem::path file = folders_.keptPassFile(id, progress.pass);
            std::filesystem::create_directories(file.parent_path());
            const std::vector<uint8_t> exr = encodeExr(image, passMetadata(settings, progress, image.exposure()));
            writeFileAtomically(file, std::string(exr.begin(), exr.end()));
            table_.addKeptPass(id, progress.pass);
        } catch (const std::exception& e) {
            spdlog::warn("job {}: pass {} not kept: {}", id, progress.pass, e.what());
        }
    }
    std::lock_guard lock(logsMutex_);
    auto [log, first] = logs_.try_emplace(id);
    if (first) log->second.history = ProgressHistory::load(folders_.progressFile(id));
    log->second.history.figures.update(pass);
    progress.figures = log->second.history.figures;
    log->second.history.add(progress);
    const auto now = std::chrono::steady_clock::now();
    if (now - log->second.saved >= std::chrono::seconds(1)) {
        log->second.saved = now;
        try {
            log->second.history.save(folders_.progressFile(id));
        } catch (const std::exception& e) {
            spdlog::warn("job {}: progress history not saved: {}", id, e.what());
        }
    }
}

void JobRunner::saveHistory(const std::string& id) {
    std::lock_guard lock(logsMutex_);
    auto log = logs_.find(id);
    if (log == logs_.end()) return;
    try {
        log->second.history.save(folders_.progressFile(id));
    } catch (const std::exception& e) {
        spdlog::warn("job {}: progress history not saved: {}", id, e.what());
    }
    logs_.erase(log);
}

void JobRunner::finish(const std::string& id, JobStatus status, const std::string& error) {
    // Files first, then the status: whoever sees the job finished finds its images on disk.
    if (status != JobStatus::Failed) writeImages(id);
    // A completed job keeps its checkpoint: it can render more passes from it.
    std::error_code ec;
    if (status != JobStatus::Completed) std::filesystem::remove(folders_.checkpointFile(id), ec);
    // The log's last line too: a client that sees the status reads it (the render has stopped,
    // so its progress is final).
    const JobProgress progress = table_.find(id)->progress;
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, "%.1f", progress.elapsedSeconds);
    appendJobLog(folders_.logFile(id), std::string(toString(status)) + " after " + std::to_string(progress.pass) +
                                           " passes, " + elapsed + " s of rendering" +
                                           (error.empty() ? "" : ": " + error));
    JobRecord job = table_.finish(id, status, error, utcNowIso8601());
    if (status == JobStatus::Failed) spdlog::warn("job {} failed: {}", id, error);
    else spdlog::info("job {} {} after {} passes", id, toString(status), job.progress.pass);
    store_.update(job);
    hub_.publish(job, eventTypeFor(status));
    images_.drop(id);
}

void JobRunner::pause(const std::string& id) {
    writeImages(id);  // served from disk while paused
    appendJobLog(folders_.logFile(id), "paused after pass " + std::to_string(table_.find(id)->progress.pass));
    JobRecord job = table_.markPaused(id, utcNowIso8601());
    store_.update(job);
    hub_.publish(job, std::nullopt);
    images_.drop(id);
}

void JobRunner::writeImages(const std::string& id) {
    for (ImageFormat format : {ImageFormat::Png, ImageFormat::Exr})
        if (std::optional<EncodedImage> image = images_.get(id, format, Freshness::LatestPass))
            writeFileAtomically(folders_.imageFile(id, format), *image->bytes);
}

}  // namespace photon::server
