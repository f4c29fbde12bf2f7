#include "integrators/common/pixel_mean.h"
#include "integrators/common/checkpoint.h"
#include "integrators/common/milliseconds_since.h"
#include "integrators/common/pixel_loop.h"

namespace photon {

PixelMeanIntegrator::PixelMeanIntegrator(std::shared_ptr<const Scene> scene)
    : scene_(std::move(scene)), width_(scene_->camera().width()), height_(scene_->camera().height()),
      sum_(static_cast<size_t>(width_) * height_), pass_(sum_.size()), halves_(sum_.size()),
      lightsInView_(*scene_) {}

bool PixelMeanIntegrator::renderPass(const CancelToken& cancel) {
    stats_ = PassStats{};
    if (!preparePass(cancel)) return false;
    const RenderSettings& s = scene_->settings();
    auto start = std::chrono::steady_clock::now();
    const RngStream stream(s.seed, static_cast<uint64_t>(passes_), StreamPurpose::Camera);
    const bool stratified = s.sampler == SamplerKind::Sobol;
    const Camera& camera = scene_->camera();
    forEachPixel(width_, height_, stream, cancel, [&](int x, int y, size_t index, Rng& rng) {
        PathSampler sampler = PathSampler::of(stratified, rng, s.seed, passes_, index, 0);
        Vec2 uFilm, uLens{0.5f, 0.5f};
        if (stratified) {
            uFilm = sampler.get2D();
            if (camera.hasLens()) uLens = sampler.get2D();
        } else {
            // The lens's numbers first, then y's, then x's: the order these were always drawn in.
            uLens = {rng.uniform(), rng.uniform()};
            const float uy = rng.uniform();
            uFilm = {rng.uniform(), uy};
        }
        const Camera::PixelSample sample = camera.samplePixel(x, y, uFilm, uLens);
        pass_[index] = radiance(sample.ray, sampler) * sample.weight;
    });
    if (cancel.cancelled()) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = 0; i < sum_.size(); ++i) {
        sum_[i] += pass_[i];
        halves_.add(passes_, i, luminance(pass_[i]));
    }
    halves_.countPass(passes_);
    ++passes_;
    stats_.cameraRays = static_cast<int64_t>(sum_.size());
    stats_.cameraMs = millisecondsSince(start);
    return true;
}

Image PixelMeanIntegrator::snapshot() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return snapshotLocked();
}

std::optional<PixelErrors> PixelMeanIntegrator::pixelErrors() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return halves_.errors(width_, height_, [&](size_t i) { return meanLocked(i); }, lightsInView_, 0.5);
}

Image PixelMeanIntegrator::snapshotLocked() const {
    Image image(width_, height_);
    if (passes_ == 0) return image;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)
            image.set(x, y, meanLocked(static_cast<size_t>(y) * width_ + x));
    return image;
}

void PixelMeanIntegrator::saveState(std::ostream& out) const {
    std::lock_guard<std::mutex> lock(mutex_);
    writeCheckpointHeader(out, checkpointKey(scene_->settings(), width_, height_));
    writeRaw(out, &passes_, 1);
    writeRaw(out, sum_.data(), sum_.size());
    halves_.save(out);
}

void PixelMeanIntegrator::restoreState(std::istream& in) {
    readCheckpointHeader(in, checkpointKey(scene_->settings(), width_, height_));
    int passes = readPassCount(in);
    std::vector<Color> sum(sum_.size());
    readRaw(in, sum.data(), sum.size());
    for (Color c : sum)
        if (!isFiniteNonNegative(c)) throw CheckpointError("checkpoint: invalid pixel sum");
    std::lock_guard<std::mutex> lock(mutex_);
    halves_.restore(in, passes);  // last: it checks the end, and commits only if all is well
    passes_ = passes;
    sum_ = std::move(sum);
}

}  // namespace photon
