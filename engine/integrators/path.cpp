// Unidirectional path tracer with next-event estimation: the independent reference the
// photon mappers are tested against. One sample per pixel per pass.
#include <tbb/parallel_for.h>
#include <mutex>
#include <vector>
#include "checkpoint.h"
#include "direct_lighting.h"
#include "integrator.h"
#include "path.h"

namespace photon {

namespace {

class PathIntegrator final : public Integrator {
public:
    explicit PathIntegrator(std::shared_ptr<const Scene> scene)
        : scene_(std::move(scene)), width_(scene_->camera().width()), height_(scene_->camera().height()),
          sum_(static_cast<size_t>(width_) * height_), pass_(sum_.size()) {}

    bool renderPass(const CancelToken& cancel) override {
        const RenderSettings& s = scene_->settings();
        tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                if (cancel.cancelled()) return;
                for (int x = 0; x < width_; ++x) {
                    size_t index = static_cast<size_t>(y) * width_ + x;
                    Rng rng(s.seed, static_cast<uint64_t>(passes_), index, StreamPurpose::Camera);
                    Ray ray = scene_->camera().generateRay(static_cast<float>(x) + rng.uniform(),
                                                           static_cast<float>(y) + rng.uniform(),
                                                           {rng.uniform(), rng.uniform()});
                    pass_[index] = traceRadiance(*scene_, ray, rng, s.maxDepth);
                }
            }
        });
        if (cancel.cancelled()) return false;
        std::lock_guard<std::mutex> lock(mutex_);
        for (size_t i = 0; i < sum_.size(); ++i) sum_[i] += pass_[i];
        ++passes_;
        stats_.cameraRays = static_cast<int64_t>(sum_.size());
        return true;
    }

    Image snapshot() const override {
        Image image(width_, height_);
        std::lock_guard<std::mutex> lock(mutex_);
        if (passes_ == 0) return image;
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x)
                image.set(x, y, sum_[static_cast<size_t>(y) * width_ + x] / static_cast<float>(passes_));
        return image;
    }

    const PassStats& lastPassStats() const override { return stats_; }
    int passesDone() const override { return passes_; }
    size_t bytesPerPixel() const override { return 2 * sizeof(Color); }

    void saveState(std::ostream& out) const override {
        std::lock_guard<std::mutex> lock(mutex_);
        writeCheckpointHeader(out, checkpointKey(scene_->settings(), width_, height_));
        writeRaw(out, &passes_, 1);
        writeRaw(out, sum_.data(), sum_.size());
    }

    void restoreState(std::istream& in) override {
        readCheckpointHeader(in, checkpointKey(scene_->settings(), width_, height_));
        int passes = 0;
        readRaw(in, &passes, 1);
        std::vector<Color> sum(sum_.size());
        readRaw(in, sum.data(), sum.size());
        std::lock_guard<std::mutex> lock(mutex_);
        passes_ = passes;
        sum_ = std::move(sum);
    }

private:
    std::shared_ptr<const Scene> scene_;
    int width_, height_;
    std::vector<Color> sum_, pass_;
    int passes_ = 0;
    PassStats stats_;
    mutable std::mutex mutex_;
};

}  // namespace

Color traceRadiance(const Scene& scene, Ray ray, Rng& rng, int maxDepth) {
    Color L(0.0f), beta(1.0f);
    bool afterDelta = true;  // emission found by shadow rays is not counted twice
    for (int depth = 0; depth < maxDepth; ++depth) {
        SurfaceHit hit;
        if (!scene.intersect(ray, hit)) {
            if (afterDelta) L += beta * scene.environment(ray.d);
            break;
        }
        Vec3 wo = -ray.d;
        if (afterDelta) L += beta * scene.emitted(hit, wo);
        ShadingPoint sp = makeShadingPoint(scene, hit, wo);
        if (!sp.material->isDeltaOnly()) L += beta * sampleDirectLight(scene, sp, wo, rng);
        float uLobe = rng.uniform();
        Vec2 u{rng.uniform(), rng.uniform()};
        std::optional<BSDFSample> s = sp.material->sample(sp.frame.toLocal(wo), uLobe, u, sp.tint,
                                                          TransportMode::Radiance);
        if (!s) break;
        beta *= s->weight;
        afterDelta = s->delta;
        // Russian roulette after a few bounces, on the throughput's largest channel.
        if (depth >= 3) {
            float q = std::min(1.0f, maxComponent(beta));
            if (rng.uniform() >= q) break;
            beta /= q;
        }
        ray = spawnRay(hit.p, hit.ng, sp.frame.toWorld(s->wi));
    }
    return L;
}

std::unique_ptr<Integrator> makePathIntegrator(std::shared_ptr<const Scene> scene) {
    return std::make_unique<PathIntegrator>(std::move(scene));
}

}  // namespace photon
