// A render job as the service sees it: identity, lifecycle state, what it renders and how
// far it got. Plain data, copied freely between the table, the store and the API.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include <photon/progress.h>

namespace photon::server {

// Paused: stopped by a client after a pass, its checkpoint kept; it waits for a resume.
enum class JobStatus { Queued, Running, Paused, Completed, Failed, Cancelled };

const char* toString(JobStatus status);
std::optional<JobStatus> parseJobStatus(const std::string& text);
// Completed, failed and cancelled jobs never change again (except by deletion).
bool isFinished(JobStatus status);

// The effective render settings: the scene's render block with the submit overrides applied.
// Stored with the job so a restart renders exactly what was accepted.
struct JobSettings {
    int passes = 0;
    int64_t photonsPerPass = 0;
    uint64_t seed = 0;
    std::string integrator;  // "sppm" or "path"
    int width = 0, height = 0;
    std::string camera;  // the imported glTF camera asked for by name; empty: the file's first
    bool denoise = false;  // the scene asks for the denoiser: its images have a raw layer
    // render.target_error: the render stops at this estimated relative error (0: none); the
    // scene's, or the submission's target_error.
    double targetError = 0;
    bool lenient = false;  // the import leaves out what photon cannot render (ImportOptions::lenient)
};

// What a method reports besides passes and photons, as its render last reported it.
struct MethodFigures {
    int64_t patches = 0;  // radiosity: patch sides solved for
    int solverIterations = 0;
    double solverResidual = 0;
    int64_t globalMapPhotons = 0, causticMapPhotons = 0;  // photon mapping: photons stored
    // Takes the figures a pass reports (a pass that built nothing reports none).
    void update(const PassStats& pass);
};

struct JobProgress {
    int pass = 0;  // passes finished
    int64_t photonsTraced = 0;
    double meanRadius = 0;
    double elapsedSeconds = 0;
    double etaSeconds = 0;  // to the pass count, the time limit or the target error, whichever comes first
    // The image's estimated relative error (RenderProgress::relativeError), when the method
    // keeps one.
    std::optional<double> relativeError;
    MethodFigures figures;
};

struct JobRecord {
    std::string id;    // 16 lowercase hex digits
    int64_t seq = 0;   // submission order (the database row id): FIFO within a priority
    JobStatus status = JobStatus::Queued;
    int priority = 0;  // higher runs first
    std::string createdAt, startedAt, finishedAt;  // ISO 8601 UTC; empty when not yet
    std::string updatedAt;                         // the last change of any field
    std::string name;                              // see job_labels.h
    std::vector<std::string> labels;
    JobSettings settings;
    JobProgress progress;
    std::string error;  // why it failed; empty otherwise
    std::string client; // the submitter's remote address (per-client limits); not served
    int64_t uploadBytes = 0;            // of its scene and assets: the client's disk (not served)
    std::vector<std::string> warnings;  // what was accepted with a change, in plain words
    std::vector<int> keptPasses;        // earlier passes kept as images (kept_passes.h), ascending
};

}  // namespace photon::server
