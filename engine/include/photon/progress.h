// What a render reports while it runs, and how it is told to stop.
#pragma once
#include <atomic>
#include <cstdint>
#include <optional>

namespace photon {

// Set from any thread; integrators check it between work chunks inside a pass.
class CancelToken {
public:
    void cancel() { flag_.store(true, std::memory_order_relaxed); }
    bool cancelled() const { return flag_.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> flag_{false};
};

struct PassStats {
    int64_t photons = 0;         // photons emitted in the pass
    int64_t photonRays = 0;      // photon rays cast, including those that leave the scene
    int64_t photonSegments = 0;  // photon rays cast that hit something
    int64_t photonMisses = 0;    // emitted photons whose first ray hit nothing (photon map)
    int64_t cameraRays = 0;      // SPPM: rays its camera paths cast (vertices and light samples); else a pass's samples
    int64_t cameraPaths = 0;     // SPPM: camera paths traced (a pixel may trace several)
    int64_t gridEntries = 0;     // visible-point entries in the hash grid (SPPM)
    int64_t gatherCandidates = 0, gatherHits = 0;  // visible points tested and accepted by photons
    double cameraMs = 0, gridMs = 0, photonMs = 0, updateMs = 0;
    double meanRadius = 0;       // mean gather radius over pixels that have one, scene units
    // Radiosity: patch sides (unknowns), form-factor rays, Gauss-Seidel sweeps and the last
    // one's relative residual, time spent meshing and solving (first pass).
    int64_t patches = 0, formFactorRays = 0;
    int solverIterations = 0;
    double solverResidual = 0, solveMs = 0;
    // Photon mapping: photons stored in the global and caustic maps (every pass that builds
    // them, a restored render's first included).
    int64_t globalMapPhotons = 0, causticMapPhotons = 0;
};

struct RenderProgress {
    int pass = 0;               // passes finished
    int totalPasses = 0;
    int64_t photonsTraced = 0;  // photons emitted so far
    double photonsPerSecond = 0;
    double meanRadius = 0;      // scene units; 0 for integrators without a gather radius
    double elapsedSeconds = 0;
    double etaSeconds = 0;      // estimate of the time left (to the pass count, the time limit or the target error)
    // The image's estimated relative error: RMS of the pixels' standard errors over their mean
    // luminance, from two half-images (docs/error-estimate.md); none for integrators whose
    // passes are not independent estimates, and before each half has a pass.
    std::optional<double> relativeError;
    // With render.target_error: passes still to render until the estimate reaches it, from
    // the rate the estimate has fallen at over the render's latest half (until it can be
    // measured, the model's: passes^-1/2; SPPM's passes^-alpha/2).
    std::optional<double> passesToTarget;
    PassStats lastPass;
};

// Completed: the pass count; TargetError: the estimated error reached render.target_error.
enum class RenderOutcome { Completed, TimeLimit, TargetError, Cancelled };

}  // namespace photon
