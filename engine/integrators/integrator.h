// The one interface every integrator implements: render pass after pass, hand out a
// snapshot of the image so far at any time, say what the last pass did.
#pragma once
#include <istream>
#include <ostream>
#include <optional>
#include <stdexcept>
#include <photon/image.h>
#include <photon/pass_sums.h>
#include <photon/progress.h>
#include "film/pixel_errors.h"

namespace photon {

class Scene;

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
    // Integrators whose passes are independent estimates (SPPM with the global radius
    // schedule): renderPasses renders passes first .. first + count - 1 on their own,
    // leaving the state as it was (nullopt if cancelled, or if passes are not independent);
    // addPasses adds such a batch, rendered here or anywhere, to the state.
    virtual bool independentPasses() const { return false; }
    virtual std::optional<PassSums> renderPasses(int64_t first, int count, const CancelToken& cancel) {
        return std::nullopt;
    }
    // Per-pixel estimates of the image's noise from its two half-images (film/pixel_errors.h),
    // for integrators whose passes are independent estimates; nullopt for the others, and
    // for a render resumed from a checkpoint that did not keep its halves.
    virtual std::optional<PixelErrors> pixelErrors() const { return std::nullopt; }
    // Frees what only a next pass would use (SPPM's hash grid), when a render stops; a pass
    // after it allocates that again.
    virtual void releasePassBuffers() {}
    virtual void addPasses(const PassSums&) {
        throw std::logic_error("this render's passes are not independent (render.radius_schedule \"global\" makes them so)");
    }
};

}  // namespace photon
