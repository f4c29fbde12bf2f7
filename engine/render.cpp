#include <photon/render.h>
#include <chrono>
#include <sstream>
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

Renderer::Renderer(std::shared_ptr<const Scene> scene) : scene_(std::move(scene)), integrator_(makeIntegrator(scene_)) {
    progress_.totalPasses = scene_->settings().passes;
    const DenoiseSettings& denoise = scene_->settings().denoise;
    if (denoise.enabled) denoiser_ = std::make_shared<const Denoiser>(*scene_, denoise);
}

Image Renderer::snapshot() const {
    Image raw = integrator_->snapshot();
    return denoiser_ ? denoiser_->apply(raw) : raw;
}

LayeredImage Renderer::layers() const { return pendingLayers()->layers(); }

std::shared_ptr<const PendingImage> Renderer::pendingLayers() const { return pendingLayersOf(integrator_->snapshot()); }

std::shared_ptr<const PendingImage> Renderer::pendingLayersOf(Image raw) const {
    return std::make_shared<const PendingImage>(std::move(raw), denoiser_, scene_->settings().exposure);
}

bool Renderer::renderPass(const CancelToken& cancel) {
    auto start = std::chrono::steady_clock::now();
    if (!integrator_->renderPass(cancel)) return false;
    renderSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const PassStats& s = integrator_->lastPassStats();
    progress_.pass = integrator_->passesDone();
    progress_.photonsTraced += s.photons;
    progress_.photonsPerSecond = renderSeconds_ > 0 ? static_cast<double>(progress_.photonsTraced) / renderSeconds_ : 0;
    progress_.meanRadius = s.meanRadius;
    progress_.elapsedSeconds = renderSeconds_;
    progress_.lastPass = s;
    int left = std::max(0, progress_.totalPasses - progress_.pass);
    progress_.etaSeconds = renderSeconds_ / progress_.pass * left;
    double limit = scene_->settings().timeLimitSeconds;
    if (limit > 0) progress_.etaSeconds = std::min(progress_.etaSeconds, std::max(0.0, limit - renderSeconds_));
    return true;
}

bool Renderer::independentPasses() const { return integrator_->independentPasses(); }

std::optional<PassSums> Renderer::renderPasses(int64_t first, int count, const CancelToken& cancel) {
    return integrator_->renderPasses(first, count, cancel);
}

void Renderer::addPasses(const PassSums& sums) {
    integrator_->addPasses(sums);
    progress_.pass = integrator_->passesDone();
    progress_.photonsTraced += sums.count * scene_->settings().photonsPerPass;
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
    progress_.photonsTraced = photons;
    progress_.pass = integrator_->passesDone();
    progress_.elapsedSeconds = seconds;
    progress_.photonsPerSecond = seconds > 0 ? static_cast<double>(photons) / seconds : 0;
}

RenderOutcome Renderer::run(const CancelToken& cancel, const ProgressFn& onPass) {
    const double limit = scene_->settings().timeLimitSeconds;
    while (integrator_->passesDone() < progress_.totalPasses) {
        if (cancel.cancelled() || !renderPass(cancel)) return RenderOutcome::Cancelled;
        if (onPass) onPass(progress_);
        if (limit > 0 && renderSeconds_ >= limit) return RenderOutcome::TimeLimit;
    }
    return RenderOutcome::Completed;
}

}  // namespace photon
