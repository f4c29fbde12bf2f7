#include <photon/render.h>
#include <chrono>
#include <cmath>
#include <sstream>
#include "film/error_decay.h"
#include "film/pixel_errors.h"
#include "integrators/common/checkpoint.h"
#include "integrator_factory.h"
#include "post/denoiser.h"
#include "scene/scene.h"

namespace photon {

Renderer::Renderer(SceneFile scene) : Renderer(Scene::build(std::move(scene.description()))) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::rawSnapshot() const { return integrator_->snapshot(); }

Renderer::Renderer(std::shared_ptr<const Scene> scene)
    : scene_(std::move(scene)), integrator_(makeIntegrator(scene_)), errorDecay_(std::make_unique<ErrorDecay>()) {
    progress_.totalPasses = scene_->settings().passes;
    const DenoiseSettings& denoise = scene_->settings().denoise;
    if (denoise.enabled) denoiser_ = std::make_shared<const Denoiser>(*scene_, denoise);
}

Image Renderer::snapshot() const {
    Image raw = integrator_->snapshot();
    return denoiser_ ? denoiser_->apply(raw) : raw;
}

LayeredImage Renderer::layers() const { return pendingLayers()->layers(); }

std::shared_ptr<const PendingImage> Renderer::pendingLayers() const {
    return std::make_shared<const PendingImage>(integrator_->snapshot(), denoiser_, scene_->settings().exposure, errors_);
}

std::shared_ptr<const PendingImage> Renderer::pendingLayersOf(Image raw) const {
    return std::make_shared<const PendingImage>(std::move(raw), denoiser_, scene_->settings().exposure);
}

bool Renderer::renderPass(const CancelToken& cancel) {
    auto start = std::chrono::steady_clock::now();
    if (!integrator_->renderPass(cancel)) return false;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    renderSeconds_ += seconds;
    const PassStats& s = integrator_->lastPassStats();
    if (window_.photons >= 0 && s.photons != window_.photons) window_ = PassWindow{};
    window_.photons = s.photons;
    window_.passes += 1;
    window_.seconds += seconds;
    progress_.pass = integrator_->passesDone();
    progress_.photonsTraced += s.photons;
    progress_.photonsPerSecond = renderSeconds_ > 0 ? static_cast<double>(progress_.photonsTraced) / renderSeconds_ : 0;
    progress_.meanRadius = s.meanRadius;
    progress_.elapsedSeconds = renderSeconds_;
    progress_.lastPass = s;
    updateErrorEstimate();
    int left = std::max(0, progress_.totalPasses - progress_.pass);
    const double perPass = window_.seconds / window_.passes;
    progress_.etaSeconds = perPass * left;
    if (progress_.passesToTarget) progress_.etaSeconds = std::min(progress_.etaSeconds, perPass * *progress_.passesToTarget);
    double limit = scene_->settings().timeLimitSeconds;
    if (limit > 0) progress_.etaSeconds = std::min(progress_.etaSeconds, std::max(0.0, limit - renderSeconds_));
    return true;
}

// The error falls as passes^-decay, so reaching the target e_t from e after N passes takes
// N (e / e_t)^(1 / decay) passes in all; decay is measured from the render's own estimates
// (film/error_decay.h), the integrator's model rate until there are enough of them.
void Renderer::updateErrorEstimate() {
    progress_.relativeError.reset();
    progress_.passesToTarget.reset();
    errors_.reset();
    if (progress_.pass < 2) return;  // asked for only when there is one (2 bytes a pixel)
    std::optional<PixelErrors> e = integrator_->pixelErrors();
    if (!e) return;
    const double error = relativeErrorOf(*e);
    progress_.relativeError = error;
    errorDecay_->add(progress_.pass, error);
    const double target = scene_->settings().targetError;
    const double decay = errorDecay_->measured().value_or(e->decay);
    if (target > 0 && decay > 0) progress_.passesToTarget = passesToTarget(progress_.pass, error, target, decay);
    errors_ = std::make_shared<const PixelErrors>(std::move(*e));
}

bool Renderer::targetErrorReached() const {
    const double target = scene_->settings().targetError;
    return target > 0 && progress_.relativeError && *progress_.relativeError <= target;
}

bool Renderer::independentPasses() const { return integrator_->independentPasses(); }

std::optional<PassSums> Renderer::renderPasses(int64_t first, int count, const CancelToken& cancel) {
    return integrator_->renderPasses(first, count, cancel);
}

void Renderer::addPasses(const PassSums& sums) {
    integrator_->addPasses(sums);
    progress_.pass = integrator_->passesDone();
    progress_.photonsTraced += sums.count * scene_->settings().photonsPerPass;
    updateErrorEstimate();
}

void Renderer::saveCheckpoint(std::ostream& out) const {
    std::ostringstream body;
    writeRaw(body, &progress_.photonsTraced, 1);
    writeRaw(body, &renderSeconds_, 1);
    integrator_->saveState(body);
    const std::string sealed = sealCheckpoint(std::move(body).str());
    writeRaw(out, sealed.data(), sealed.size());
}

void Renderer::restoreCheckpoint(std::istream& in) {
    // The integrator restores all or nothing; the progress is only taken once it has.
    std::ostringstream whole;
    whole << in.rdbuf();
    const std::string sealed = std::move(whole).str();
    ViewInputStream body(unsealCheckpoint(sealed));
    int64_t photons = 0;
    double seconds = 0;
    readRaw(body, &photons, 1);
    readRaw(body, &seconds, 1);
    if (photons < 0 || !(seconds >= 0 && seconds <= 1e12)) throw CheckpointError("checkpoint: invalid progress");
    integrator_->restoreState(body);
    renderSeconds_ = seconds;
    window_ = PassWindow{-1, integrator_->passesDone(), seconds};
    progress_.photonsTraced = photons;
    progress_.pass = integrator_->passesDone();
    progress_.elapsedSeconds = seconds;
    progress_.photonsPerSecond = seconds > 0 ? static_cast<double>(photons) / seconds : 0;
    updateErrorEstimate();
}

RenderOutcome Renderer::run(const CancelToken& cancel, const ProgressFn& onPass) {
    const RenderOutcome outcome = runPasses(cancel, onPass);
    // The final image and its files are made after this: without the grid a 3840 x 2160
    // SPPM frame's peak is then well below the one while passes run (docs/sppm.md#memory).
    integrator_->releasePassBuffers();
    return outcome;
}

RenderOutcome Renderer::runPasses(const CancelToken& cancel, const ProgressFn& onPass) {
    const double limit = scene_->settings().timeLimitSeconds;
    while (integrator_->passesDone() < progress_.totalPasses) {
        if (cancel.cancelled() || !renderPass(cancel)) return RenderOutcome::Cancelled;
        if (onPass) onPass(progress_);
        if (limit > 0 && renderSeconds_ >= limit) return RenderOutcome::TimeLimit;
        if (targetErrorReached()) return RenderOutcome::TargetError;
    }
    return RenderOutcome::Completed;
}

}  // namespace photon
