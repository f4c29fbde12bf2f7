#include "render.h"

namespace photon {

Renderer::Renderer(std::shared_ptr<const Scene> scene) : scene_(std::move(scene)), integrator_(makeIntegrator(scene_)) {
    progress_.totalPasses = scene_->settings().passes;
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
