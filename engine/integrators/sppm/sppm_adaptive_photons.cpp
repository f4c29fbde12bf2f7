// render.adaptive_photons and render.adaptive_camera_paths: each pass's measurements go to
// the photon budget (photon_budget.h), which at its decisions sets the photons of the
// passes that follow, and at the same decisions the camera paths' scale is set
// (camera_paths.h).
#include "integrators/sppm/sppm.h"
#include <tbb/parallel_for.h>
#include <algorithm>

namespace photon {

void SppmIntegrator::measurePhotonVariance(int first, int end) {
    tbb::parallel_for(first, end, [&](int y) {
        double sum = 0;
        for (size_t i = static_cast<size_t>(y) * width_; i < static_cast<size_t>(y + 1) * width_; ++i) {
            const std::optional<Color> photons = passPhotonEstimate(i);
            if (!photons) continue;
            const double p = luminance(*photons);
            sum += p * p / static_cast<double>(result(i).photonCount);
        }
        rowVariance_[static_cast<size_t>(y)] = sum;
    });
}

double SppmIntegrator::photonVarianceOfPass() const {
    // Row by row, each row's sum in pixel order: the same on any number of threads and in
    // any band count, and so is the budget's choice.
    double sum = 0;
    for (double row : rowVariance_) sum += row;
    return sum / static_cast<double>(std::max<size_t>(pixels_.size(), 1));
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
                            passVariance * static_cast<double>(pixels_.size()));
    }
}

}  // namespace photon
