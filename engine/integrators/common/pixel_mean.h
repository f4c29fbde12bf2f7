// Integrators whose image is the running mean of one independent radiance sample per
// pixel per pass (the path tracer, radiosity's camera pass): the pass loop, snapshot and
// checkpoint of per-pixel sums live here once.
#pragma once
#include <mutex>
#include <vector>
#include "integrators/common/pass_halves.h"
#include "math/path_sampler.h"
#include "scene/scene.h"
#include "integrators/integrator.h"

namespace photon {

class PixelMeanIntegrator : public Integrator {
public:
    bool renderPass(const CancelToken& cancel) override;
    Image snapshot() const override;
    const PassStats& lastPassStats() const override { return stats_; }
    int passesDone() const override { return passes_; }
    size_t bytesPerPixel() const override {
        return 2 * sizeof(Color) + 2 * sizeof(float) +
               lightsInView_.bytes() / std::max<size_t>(static_cast<size_t>(width_) * static_cast<size_t>(height_), 1);
    }
    // The pixel sums, their halves and the pass count: each pass's samples are keyed by
    // pass and pixel, so that is the whole state.
    void saveState(std::ostream& out) const override;
    void restoreState(std::istream& in) override;
    std::optional<PixelErrors> pixelErrors() const override;

protected:
    explicit PixelMeanIntegrator(std::shared_ptr<const Scene> scene);
    // Work before a pass's camera rays (e.g. a solve on the first pass); false if cancelled.
    virtual bool preparePass(const CancelToken& cancel) { return true; }
    // Radiance arriving along a camera ray; `sampler` draws the path's numbers for this pass
    // (render.sampler), its rng() is the pixel's stream.
    virtual Color radiance(const Ray& ray, PathSampler& sampler) const = 0;

    std::shared_ptr<const Scene> scene_;
    PassStats stats_;

private:
    int width_, height_;
    Image snapshotLocked() const;
    // Pixel i of the image: the mean of its passes (black before the first).
    Color meanLocked(size_t i) const { return passes_ == 0 ? Color(0.0f) : sum_[i] / static_cast<float>(passes_); }

    std::vector<Color> sum_, pass_;
    PassHalves halves_;
    LightsInView lightsInView_;
    int passes_ = 0;
    mutable std::mutex mutex_;
};

}  // namespace photon
