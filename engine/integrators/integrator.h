// The one interface every integrator implements: render pass after pass, hand out a
// snapshot of the image so far at any time, say what the last pass did.
#pragma once
#include <atomic>
#include <cstdint>
#include <istream>
#include <ostream>
#include <memory>
#include "../film/image.h"

namespace photon {

class Scene;

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
    int64_t cameraRays = 0;
    int64_t gridEntries = 0;     // visible-point entries in the hash grid (SPPM)
    int64_t gatherCandidates = 0, gatherHits = 0;  // visible points tested and accepted by photons
    double cameraMs = 0, gridMs = 0, photonMs = 0, updateMs = 0;
    double meanRadius = 0;       // mean gather radius over pixels that have one, scene units
    // Radiosity: patch sides (unknowns), form-factor rays, Gauss-Seidel sweeps and the last
    // one's relative residual, time spent meshing and solving (first pass).
    int64_t patches = 0, formFactorRays = 0;
    int solverIterations = 0;
    double solverResidual = 0, solveMs = 0;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Renders the next pass. Returns false if cancelled before the pass finished; the
    // image and state are then as they were after the previous pass.
    virtual bool renderPass(const CancelToken& cancel) = 0;
    // The image after the passes done so far; safe to call while renderPass runs.
    virtual Image snapshot() const = 0;
    virtual const PassStats& lastPassStats() const = 0;
    virtual int passesDone() const = 0;
    // Bytes of state kept per pixel (persistent plus per-pass), for memory accounting.
    virtual size_t bytesPerPixel() const = 0;
    // The whole state after the last finished pass (see checkpoint.h). restoreState takes
    // what saveState wrote for the same scene and settings, else throws CheckpointError.
    virtual void saveState(std::ostream& out) const = 0;
    virtual void restoreState(std::istream& in) = 0;
};

// Makes the integrator that scene->settings().integrator names.
std::unique_ptr<Integrator> makeIntegrator(std::shared_ptr<const Scene> scene);

}  // namespace photon
