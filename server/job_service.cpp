#include "job_service.h"
#include <algorithm>
#include <spdlog/spdlog.h>
#include "job_labels.h"
#include "job_log.h"
#include "clock.h"
#include "errors.h"
#include "safe_files.h"
#include "texture_limits.h"

namespace photon::server {

namespace {

[[noreturn]] void notFound(const std::string& id) { throw ServiceError(ErrorKind::NotFound, "no job " + id); }

}  // namespace

JobService::JobService(const ServiceConfig& config)
    : limits_(config.limits),
      folders_(config.dataDir),
      store_(folders_.databaseFile()),
      farm_(config.redis ? std::make_unique<farm::FarmDispatcher>(*config.redis, "photon-server") : nullptr),
      runner_(table_, store_, folders_, images_, hub_, metrics_, config.checkpointSeconds,
              FarmUse{farm_.get(), config.farmBatchPasses}) {
    restore();
    workers_ = std::make_unique<WorkerPool>(queue_, runner_, farm_ ? config.farmJobs : config.workers);
    if (farm_ && config.workers > 0)
        farmWorkers_ = std::make_unique<farm::LocalWorkers>(*config.redis, config.workers, folders_.farmScratchDir());
}

JobService::~JobService() { shutdown(); }

std::optional<FarmFigures> JobService::farmFigures() {
    if (!farm_) return std::nullopt;
    try {
        FarmFigures f;
        const farm::FarmCoordinator::Counters c = farm_->counters();
        f.queueDepth = farm_->queueDepth();
        f.results = c.results, f.duplicates = c.duplicates, f.stale = c.stale;
        f.batches = c.batches, f.batchSeconds = c.batchSeconds;
        for (const farm::WorkerInfo& w : farm_->workers())
            f.workers.push_back({w.name, w.host, w.threads, w.passesPerSecond, w.batches, w.claimed, !w.item.empty(),
                                 w.item.substr(0, w.item.find('/'))});
        return f;
    } catch (const std::exception& e) {
        spdlog::warn("render farm: {}", e.what());
        return std::nullopt;
    }
}

void JobService::restore() {
    for (JobRecord& job : store_.loadAll()) {
        if (job.status == JobStatus::Running) {
            // The image of an interrupted render was never saved: start it over.
            job.status = JobStatus::Queued;
            job.startedAt.clear();
            job.progress = JobProgress{};
            store_.update(job);
        }
        job.keptPasses = folders_.keptPasses(job.id);
        const ProgressHistory history = ProgressHistory::load(folders_.progressFile(job.id));
        job.progress.figures = history.figures;
        if (!history.points().empty()) job.progress.relativeError = history.points().back().relativeError;
        table_.insert(job);
        hub_.publish(job, std::nullopt);
        if (job.status == JobStatus::Queued) queue_.push(job.id, job.priority, job.seq);
    }
}

std::unique_ptr<StagedUpload> JobService::newUpload() const {
    return std::make_unique<StagedUpload>(folders_.newStagingDir(), size_t(limits_.maxAssetBytes));
}

std::optional<JobRecord> JobService::replay(const std::string& key, const std::string& digest) {
    std::optional<IdempotencyEntry> earlier = store_.findKey(key, unixNowSeconds());
    if (!earlier) return std::nullopt;
    if (earlier->requestHash != digest)
        throw ServiceError(ErrorKind::LimitExceeded, "Idempotency-Key reused with a different request");
    return table_.find(earlier->jobId);  // deleting a job forgets its key: normally found
}

void JobService::checkAdmission(const std::string& client, int64_t uploadBytes) const {
    int64_t stored = table_.activeBytesOf(client);
    if (stored + uploadBytes > limits_.maxClientBytes)
        throw ServiceError(ErrorKind::TooManyRequests,
                           "client " + client + " has " + std::to_string(stored) +
                               " bytes of scenes and assets in jobs queued or running; with this job's " +
                               std::to_string(uploadBytes) + " that exceeds the server limit per client of " +
                               std::to_string(limits_.maxClientBytes) + " (" + optionOf(&Limits::maxClientBytes) +
                               "); retry when one has finished");
    int64_t active = table_.activeJobsOf(client);
    if (active >= limits_.maxJobsPerClient)
        throw ServiceError(ErrorKind::TooManyRequests,
                           "client " + client + " has " + std::to_string(active) +
                               " jobs queued or running, the server limit per client is " +
                               std::to_string(limits_.maxJobsPerClient) + " (" +
                               optionOf(&Limits::maxJobsPerClient) + "); retry when one has finished");
    int64_t queued = table_.countByStatus().at(JobStatus::Queued);
    if (queued >= limits_.maxQueuedJobs)
        throw ServiceError(ErrorKind::Unavailable, "the queue is full: " + std::to_string(queued) +
                                                       " jobs queued, the server limit is " +
                                                       std::to_string(limits_.maxQueuedJobs) + " (" +
                                                       optionOf(&Limits::maxQueuedJobs) + "); retry later");
}

std::string JobService::unusedId() const {
    for (;;) {
        std::string id = randomJobId();
        if (!table_.contains(id) && !std::filesystem::exists(folders_.jobDir(id))) return id;
    }
}

SubmitResult JobService::submit(StagedUpload& upload, const SubmitRequest& request) {
    // Held until the job is stored: a concurrent retry with the same key waits, then replays.
    std::optional<KeyLocks::Guard> keyGuard;
    std::optional<IdempotencyEntry> key;
    if (request.idempotencyKey) {
        keyGuard.emplace(keyLocks_, *request.idempotencyKey);
        if (std::optional<JobRecord> earlier = replay(*request.idempotencyKey, request.digest))
            return {*earlier, false};
        key = IdempotencyEntry{*request.idempotencyKey, request.digest, "", unixNowSeconds()};
    }
    if (auto problem = jobNameProblem(request.options.name)) throw ServiceError(ErrorKind::BadRequest, *problem);
    if (auto problem = jobLabelsProblem(request.options.labels)) throw ServiceError(ErrorKind::BadRequest, *problem);
    checkAdmission(request.client, 0);  // early, before the costly validation
    upload.endAsset();
    checkTextureSizes(upload.dir(), limits_);
    JobRecord job;
    // Stored first: an imported scene is read from its file, next to its assets.
    const std::filesystem::path sceneFile = upload.dir() / upload.sceneFileName();
    guardStorage("storing the scene", [&] { writeFileAtomically(sceneFile, upload.sceneText()); });
    AcceptedScene scene = validateScene(upload.sceneText(), sceneFile, request.options, limits_);
    job.settings = scene.settings;
    job.warnings = scene.warnings;
    // Files the scene does not name are not kept: they would only take the client's disk.
    // An importer also reads files the scene's list leaves out (included .pbrt files, PLY
    // meshes, glTF buffers), so an imported scene keeps every file uploaded with it.
    if (!scene.imported)
        for (const std::string& name : upload.keepOnly(scene.files))
            job.warnings.push_back("asset \"" + name + "\" is not used by the scene and was not stored");
    job.uploadBytes = upload.storedBytes();
    job.priority = request.options.priority;
    job.name = request.options.name;
    job.labels = request.options.labels;
    job.client = request.client;

    std::lock_guard admit(admission_);
    checkAdmission(request.client, job.uploadBytes);
    job.id = unusedId();
    job.createdAt = job.updatedAt = utcNowIso8601();
    guardStorage("storing the job", [&] { folders_.commit(upload.dir(), job.id); });
    upload.markCommitted();
    try {
        job.seq = guardStorage("recording the job", [&] { return store_.insert(job, key); });
    } catch (...) {
        folders_.remove(job.id);
        throw;
    }
    logAccepted(job);
    table_.insert(job);
    hub_.publish(job, std::nullopt);
    queue_.push(job.id, job.priority, job.seq);
    return {job, true};
}

void JobService::logAccepted(const JobRecord& job) const {
    const JobSettings& s = job.settings;
    appendJobLog(folders_.logFile(job.id),
                 "accepted from " + job.client + ": " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", " +
                     // photons_per_pass as the scene gives it: SPPM may choose its own after it.
                     std::to_string(s.passes) + " passes, photons_per_pass " + std::to_string(s.photonsPerPass) + ", seed " +
                     std::to_string(s.seed) + ", " + s.integrator + ", priority " + std::to_string(job.priority));
    for (const std::string& warning : job.warnings) appendJobLog(folders_.logFile(job.id), "warning: " + warning);
}

std::string JobService::log(const std::string& id) const {
    if (!table_.contains(id)) notFound(id);
    return readWholeFile(folders_.logFile(id)).value_or("");
}

JobRecord JobService::get(const std::string& id) const {
    std::optional<JobRecord> job = table_.find(id);
    if (!job) notFound(id);
    return *job;
}

JobTable::Page JobService::list(const JobFilter& filter, size_t limit, size_t offset) const {
    return table_.list(filter, limit, offset);
}

JobService::CancelResult JobService::cancel(const std::string& id) {
    JobRecord job;
    switch (table_.cancel(id, utcNowIso8601(), job)) {
        case JobTable::CancelResult::NotFound: notFound(id);
        case JobTable::CancelResult::AlreadyFinished:
            throw ServiceError(ErrorKind::Conflict, "job " + id + " is already " + toString(job.status));
        case JobTable::CancelResult::Requested:
            appendJobLog(folders_.logFile(id), "cancel requested; the render stops after its current pass");
            return {job, true};
        case JobTable::CancelResult::CancelledNow:
            appendJobLog(folders_.logFile(id), "cancelled while queued");
            break;
    }
    queue_.remove(id);
    store_.update(job);
    hub_.publish(job, EventType::Cancelled);
    return {job, false};
}

JobService::CancelResult JobService::pause(const std::string& id) {
    JobRecord job;
    switch (table_.pause(id, utcNowIso8601(), job)) {
        case JobTable::PauseResult::NotFound: notFound(id);
        case JobTable::PauseResult::NotPausable:
            throw ServiceError(ErrorKind::Conflict, "job " + id + " is " + toString(job.status) +
                                                        ": only a queued or running job can be paused");
        case JobTable::PauseResult::Requested:
            appendJobLog(folders_.logFile(id), "pause requested; the render stops after its current pass");
            return {job, true};
        case JobTable::PauseResult::PausedNow: break;
    }
    queue_.remove(id);
    store_.update(job);
    hub_.publish(job, std::nullopt);
    appendJobLog(folders_.logFile(id), "paused while queued");
    return {job, false};
}

JobRecord JobService::resume(const std::string& id) {
    JobRecord job;
    switch (table_.resume(id, utcNowIso8601(), job)) {
        case JobTable::ResumeResult::NotFound: notFound(id);
        case JobTable::ResumeResult::NotPaused:
            throw ServiceError(ErrorKind::Conflict, "job " + id + " is " + toString(job.status) + ", not paused");
        case JobTable::ResumeResult::Resumed: break;
    }
    store_.update(job);
    // Logged before the push: a free worker may take the job at once and log its own start.
    appendJobLog(folders_.logFile(id), "resumed: queued again");
    queue_.push(id, job.priority, job.seq);
    hub_.publish(job, std::nullopt);
    return job;
}

JobRecord JobService::continueJob(const std::string& id, int64_t morePasses) {
    JobRecord before = get(id);
    if (morePasses < 1) throw ServiceError(ErrorKind::BadRequest, "passes: must be an integer >= 1");
    checkLimit(ErrorKind::LimitExceeded, "the number of passes, those to come included",
               before.progress.pass + morePasses, limits_, &Limits::maxPasses);
    std::error_code ec;
    if (before.status == JobStatus::Completed && !std::filesystem::exists(folders_.checkpointFile(id), ec))
        throw ServiceError(ErrorKind::Conflict, "job " + id + " kept no checkpoint to render on from");
    JobRecord job;
    switch (table_.continueWith(id, int(morePasses), utcNowIso8601(), job)) {
        case JobTable::ContinueResult::NotFound: notFound(id);
        case JobTable::ContinueResult::NotCompleted:
            throw ServiceError(ErrorKind::Conflict, "job " + id + " is " + toString(job.status) +
                                                        ": only a completed job can render more passes");
        case JobTable::ContinueResult::Continued: break;
    }
    store_.update(job);
    queue_.push(id, job.priority, job.seq);
    hub_.publish(job, std::nullopt);
    appendJobLog(folders_.logFile(id), std::to_string(morePasses) + " more passes asked: on to pass " +
                                           std::to_string(job.settings.passes));
    return job;
}

JobRecord JobService::setPriority(const std::string& id, int priority) {
    JobRecord job;
    switch (table_.setPriority(id, priority, utcNowIso8601(), job)) {
        case JobTable::ChangeResult::NotFound: notFound(id);
        case JobTable::ChangeResult::NotQueued:
            throw ServiceError(ErrorKind::Conflict, "job " + id + " is " + toString(job.status) +
                                                        ": its priority can change only while it is queued");
        case JobTable::ChangeResult::Changed: break;
    }
    // Taken out and put back: if a worker took it meanwhile, it is gone and stays gone.
    if (queue_.remove(id)) queue_.push(id, job.priority, job.seq);
    store_.update(job);
    appendJobLog(folders_.logFile(id), "priority set to " + std::to_string(priority));
    hub_.publish(job, std::nullopt);
    return job;
}

std::string JobService::scene(const std::string& id) const {
    if (!table_.contains(id)) notFound(id);
    std::optional<std::string> text = readWholeFile(folders_.sceneFile(id));
    if (!text) throw ServiceError(ErrorKind::NotFound, "job " + id + " has no scene file");
    return *text;
}

std::string JobService::sceneFileName(const std::string& id) const {
    if (!table_.contains(id)) notFound(id);
    return folders_.sceneFile(id).filename().string();
}

SubmitResult JobService::clone(const std::string& id, const SubmitOptions& overrides, const std::string& client) {
    JobRecord original = get(id);
    std::unique_ptr<StagedUpload> upload = newUpload();
    upload->sceneText() = scene(id);
    upload->setSceneFileName(folders_.sceneFile(id).filename().string());
    // Every file of the job's folder but what rendering wrote: submit() keeps those the
    // scene names, and holds them to the asset limits like an upload.
    const std::filesystem::path folder = folders_.jobDir(id);
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(folder, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file() || it->is_symlink()) continue;
        std::string name = std::filesystem::relative(it->path(), folder).generic_string();
        if (JobFolders::isServiceFile(name)) continue;
        std::optional<std::string> bytes = readWholeFile(it->path());
        if (!bytes) continue;
        upload->beginAsset("clone of " + id, name);
        upload->appendAsset(bytes->data(), bytes->size());
    }
    SubmitOptions options = overrides;
    if (!options.passes) options.passes = original.settings.passes;
    if (!options.photonsPerPass) options.photonsPerPass = original.settings.photonsPerPass;
    if (!options.seed) options.seed = original.settings.seed;
    if (!options.camera && !original.settings.camera.empty()) options.camera = original.settings.camera;
    if (!options.lenient) options.lenient = original.settings.lenient;
    if (options.name.empty()) options.name = original.name;
    if (options.labels.empty()) options.labels = original.labels;
    SubmitResult result = submit(*upload, {options, client, std::nullopt, ""});
    appendJobLog(folders_.logFile(result.job.id), "a clone of job " + id);
    return result;
}

void JobService::remove(const std::string& id) {
    switch (table_.remove(id)) {
        case JobTable::RemoveResult::NotFound: notFound(id);
        case JobTable::RemoveResult::NotFinished:
            throw ServiceError(ErrorKind::Conflict, "job " + id + " has not finished; cancel it first");
        case JobTable::RemoveResult::Removed: break;
    }
    guardStorage("removing job " + id, [&] { store_.remove(id); });
    folders_.remove(id);
    images_.drop(id);
    hub_.forget(id);
}

std::optional<EncodedImage> JobService::image(const std::string& id, ImageFormat format) {
    // Running jobs are served from memory; the runner writes the files before it marks a
    // job finished and drops the memory copy after, so one of the two always answers.
    if (std::optional<EncodedImage> latest = images_.get(id, format)) return latest;
    std::optional<JobRecord> job = table_.find(id);
    if (!job) notFound(id);
    // On disk: a finished or paused job's, or the last of one rendering on (none before).
    std::optional<std::string> bytes = readWholeFile(folders_.imageFile(id, format));
    if (!bytes) return std::nullopt;
    return EncodedImage{job->progress.pass, std::make_shared<const std::string>(std::move(*bytes)), {}};
}

EncodedImage JobService::keptPass(const std::string& id, int pass) {
    std::optional<JobRecord> job = table_.find(id);
    if (!job) notFound(id);
    const std::vector<int>& kept = job->keptPasses;
    std::optional<std::string> bytes;
    if (std::binary_search(kept.begin(), kept.end(), pass)) bytes = readWholeFile(folders_.keptPassFile(id, pass));
    if (!bytes) {
        std::string list;
        for (int k : kept) list += (list.empty() ? "" : ", ") + std::to_string(k);
        throw ServiceError(ErrorKind::NotFound, "job " + id + " kept no image of pass " + std::to_string(pass) +
                                                    " (it keeps the first pass at or after each power of two; kept: " +
                                                    (list.empty() ? "none yet" : list) + ")");
    }
    return EncodedImage{pass, std::make_shared<const std::string>(std::move(*bytes)), {}};
}

std::vector<ProgressPoint> JobService::progressHistory(const std::string& id) {
    if (!table_.find(id)) notFound(id);
    return ProgressHistory::load(folders_.progressFile(id)).points();
}

void JobService::shutdown() {
    hub_.shutdown();
    queue_.close();
    table_.interruptAll();
    if (workers_) workers_->join();
    farmWorkers_.reset();
}

}  // namespace photon::server
