// render.adaptive_photons and render.adaptive_camera_paths: each pass's measurements go to
// the photon budget (photon_budget.h), which at its decisions sets the photons of the
// passes that follow, and at the same decisions the camera paths' scale is set
// (camera_paths.h).
#include "integrators/sppm/sppm.h"
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <functional>

namespace photon {

double SppmIntegrator::photonVarianceOfPass() const {
    // parallel_deterministic_reduce splits the same way on any number of threads, so the
    // sum's rounding, and with it the budget's choice, does not depend on them.
    const double sum = tbb::parallel_deterministic_reduce(
        tbb::blocked_range<size_t>(0, results_.size(), 4096), 0.0,
        [&](const tbb::blocked_range<size_t>& range, double partial) {
            for (size_t i = range.begin(); i < range.end(); ++i) {
                const std::optional<Color> photons = passPhotonEstimate(i);
                if (!photons) continue;
                const double p = luminance(*photons);
                partial += p * p / static_cast<double>(results_[i].photonCount);
            }
            return partial;
        },
        std::plus<double>());
    return results_.empty() ? 0.0 : sum / static_cast<double>(results_.size());
}

void SppmIntegrator::adaptToError() {
    // The pass's costs in camera rays: its camera paths and grid, and its photons.
    const double cameraCost = static_cast<double>(stats_.cameraRays) +
                              PhotonBudget::kGridEntryCost * static_cast<double>(stats_.gridEntries);
    const double photonCost = static_cast<double>(stats_.photonRays) +
                              PhotonBudget::kCandidateCost * static_cast<double>(stats_.gatherCandidates);
    // Lightweight photon mapping in a scene without delta lobes traces no photons.
    const bool budgetsPhotons = adaptivePhotons_ && tracesPhotons_;
    // A pass that traced no photons (no visible point: SppmIntegrator::traceBands) says
    // nothing of what they cost or bring.
    if (budgetsPhotons && photonsTraced_) budget_.add({photons_, photonVarianceOfPass(), cameraCost, photonCost});
    if (!PhotonBudget::decidesAfter(passes_)) return;
    // The halves' variance of the render's mean, times the passes: a pass's own variance.
    const std::optional<ErrorMoments> errors = halves_.moments(width_, height_, [&](size_t i) { return radianceLocked(i); }, lightsInView_);
    if (!errors) return;  // resumed from a checkpoint without halves: the counts stay
    const double passVariance = errors->variance * static_cast<double>(passes_);
    if (budgetsPhotons) photons_ = budget_.next(photons_, passVariance);
    if (adaptsCameraPaths_ && stats_.cameraPaths > 0) {
        // In rays alone, a band's photon rays once: the counts then do not depend on
        // render.bands, and the image is the same in any number of bands (the grid's
        // entries and the gather's candidates, which do, cost a fifth of the rays or less).
        const double rays = static_cast<double>(stats_.cameraRays) +
                            static_cast<double>(stats_.photonRays) / static_cast<double>(bandCount());
        cameraPaths_.decide(rays, static_cast<double>(stats_.cameraRays) / static_cast<double>(stats_.cameraPaths),
                            passVariance * static_cast<double>(results_.size()));
    }
}

}  // namespace photon
