// SPPM: construction, the per-pass driver, the statistics update and snapshots.
#include "integrators/sppm/sppm.h"
#include "integrators/common/checkpoint.h"
#include <tbb/parallel_for.h>
#include <chrono>

namespace photon {

namespace {
double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

SppmIntegrator::SppmIntegrator(std::shared_ptr<const Scene> scene)
    : scene_(std::move(scene)), settings_(scene_->settings()), emitter_(*scene_, settings_.projectionMaps),
      width_(scene_->camera().width()), height_(scene_->camera().height()) {
    size_t n = static_cast<size_t>(width_) * height_;
    pixels_.resize(n);
    discs_.resize(n);
    visible_.resize(n);
    passDirect_.resize(n);
}

size_t SppmIntegrator::bytesPerPixel() const {
    return sizeof(PixelState) + sizeof(GatherDisc) + sizeof(VisiblePoint) + sizeof(Color);
}

bool SppmIntegrator::renderPass(const CancelToken& cancel) {
    stats_ = PassStats{};
    auto t0 = std::chrono::steady_clock::now();
    cameraPass(cancel);
    stats_.cameraMs = millisecondsSince(t0);
    if (cancel.cancelled()) return false;

    t0 = std::chrono::steady_clock::now();
    buildGrid();
    stats_.gridMs = millisecondsSince(t0);
    stats_.gridEntries = static_cast<int64_t>(grid_.entryCount());

    t0 = std::chrono::steady_clock::now();
    photonPass(cancel);
    stats_.photonMs = millisecondsSince(t0);
    if (cancel.cancelled()) return false;

    t0 = std::chrono::steady_clock::now();
    updateStatistics();
    stats_.updateMs = millisecondsSince(t0);
    return true;
}

void SppmIntegrator::buildGrid() {
    grid_.build(
        discs_.size(), [&](size_t i) { return discs_[i].p; }, [&](size_t i) { return discs_[i].r2; });
}

// Hachisuka & Jensen 2009, eq. 7-10: N' = N + alpha M, R'^2 = R^2 (N + alpha M)/(N + M),
// tau' = (tau + Phi) R'^2 / R^2. Photon fluxes were normalised to a mean of 1, so Phi is
// scaled back by the lights' total power here.
void SppmIntegrator::updateStatistics() {
    const double fluxUnit = scene_->lights().totalAveragePower() / kFluxScale;
    std::lock_guard<std::mutex> lock(stateMutex_);
    tbb::parallel_for(size_t(0), pixels_.size(), [&](size_t i) {
        PixelState& px = pixels_[i];
        px.directSum += passDirect_[i];
        if (px.r2 == 0) px.r2 = discs_[i].r2;  // first pass with a visible point sets the start radius
        const VisiblePoint& vp = visible_[i];
        uint32_t m = vp.photonCount;
        if (m == 0 || px.r2 == 0) return;
        Color phi{static_cast<float>(static_cast<double>(vp.flux[0]) * fluxUnit),
                  static_cast<float>(static_cast<double>(vp.flux[1]) * fluxUnit),
                  static_cast<float>(static_cast<double>(vp.flux[2]) * fluxUnit)};
        float nNew = px.n + settings_.alpha * static_cast<float>(m);
        float shrink = nNew / (px.n + static_cast<float>(m));
        px.tau = (px.tau + phi) * shrink;
        px.r2 *= shrink;
        px.n = nNew;
    });
    ++passes_;
    double radiusSum = 0;
    size_t withRadius = 0;
    for (const PixelState& px : pixels_)
        if (px.r2 > 0) {
            radiusSum += std::sqrt(px.r2);
            ++withRadius;
        }
    stats_.meanRadius = withRadius ? radiusSum / static_cast<double>(withRadius) : 0.0;
}

void SppmIntegrator::saveState(std::ostream& out) const {
    std::lock_guard<std::mutex> lock(stateMutex_);
    writeCheckpointHeader(out, checkpointKey(settings_, width_, height_));
    writeRaw(out, &passes_, 1);
    writeRaw(out, pixels_.data(), pixels_.size());
}

void SppmIntegrator::restoreState(std::istream& in) {
    readCheckpointHeader(in, checkpointKey(settings_, width_, height_));
    int passes = readPassCount(in);
    std::vector<PixelState> pixels(pixels_.size());
    readRaw(in, pixels.data(), pixels.size());
    for (const PixelState& p : pixels)
        if (!isFiniteNonNegative(p.directSum) || !isFiniteNonNegative(p.tau) || !isFiniteNonNegative(p.n) ||
            !isFiniteNonNegative(p.r2))
            throw CheckpointError("checkpoint: invalid pixel statistics");
    requireEndOfCheckpoint(in);
    std::lock_guard<std::mutex> lock(stateMutex_);
    passes_ = passes;
    pixels_ = std::move(pixels);
}

// L = direct / passes + tau / (pi R^2 N_emitted) (Hachisuka & Jensen 2009, eq. 12).
Image SppmIntegrator::snapshot() const {
    Image image(width_, height_);
    std::lock_guard<std::mutex> lock(stateMutex_);
    if (passes_ == 0) return image;
    const double emitted = static_cast<double>(passes_) * static_cast<double>(settings_.photonsPerPass);
    const float invPasses = 1.0f / static_cast<float>(passes_);
    tbb::parallel_for(0, height_, [&](int y) {
        for (int x = 0; x < width_; ++x) {
            const PixelState& px = pixels_[static_cast<size_t>(y) * width_ + x];
            Color L = px.directSum * invPasses;
            if (px.r2 > 0) L += px.tau * static_cast<float>(1.0 / (kPi * px.r2 * emitted));
            image.set(x, y, L);
        }
    });
    return image;
}

}  // namespace photon
