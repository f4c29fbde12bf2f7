#include "job_runner.h"
#include <cstdio>
#include "clock.h"
#include "render.h"
#include "scene_intake.h"

namespace photon::server {

void JobRunner::run(const std::string& id) {
    std::optional<JobTable::Started> started = table_.start(id, utcNowIso8601());
    if (!started) return;  // cancelled while it waited in the queue
    try {
        store_.update(started->job);
        hub_.publish(started->job, std::nullopt);
        Ending ending = render(*started);
        // A stop without a client's cancel is the server shutting down: the store still says
        // "running", so the next start queues the job again.
        if (ending == Ending::Interrupted) return;
        finish(id, ending == Ending::Completed ? JobStatus::Completed : JobStatus::Cancelled, "");
    } catch (const std::exception& e) {
        try {
            finish(id, JobStatus::Failed, e.what());
        } catch (const std::exception& again) {
            std::fprintf(stderr, "photon-server: job %s: %s (while recording: %s)\n", id.c_str(), again.what(),
                         e.what());
        }
    }
}

JobRunner::Ending JobRunner::render(const JobTable::Started& started) {
    const std::string& id = started.job.id;
    SceneDescription description = loadSceneFile(folders_.sceneFile(id));
    applySettings(started.job.settings, description);
    const float exposure = description.render.exposure;
    Renderer renderer(Scene::build(std::move(description)));
    double elapsedBefore = 0;
    RenderOutcome outcome = renderer.run(*started.cancel, [&](const RenderProgress& p) {
        onPass(id, renderer, p, exposure, elapsedBefore);
    });
    if (outcome != RenderOutcome::Cancelled) return Ending::Completed;  // pass count or time limit reached
    return table_.cancelRequested(id) ? Ending::Cancelled : Ending::Interrupted;
}

void JobRunner::onPass(const std::string& id, const Renderer& renderer, const RenderProgress& p, float exposure,
                       double& elapsedBefore) {
    // Between passes the snapshot is exactly the image after pass p.pass.
    images_.store(id, p.pass, std::make_shared<const Image>(renderer.snapshot()), exposure);
    JobProgress progress{p.pass, p.photonsTraced, p.meanRadius, p.elapsedSeconds, p.etaSeconds};
    hub_.publish(table_.setProgress(id, progress), EventType::Progress);
    metrics_.addPass(p.lastPass.photons, p.elapsedSeconds - elapsedBefore);
    elapsedBefore = p.elapsedSeconds;
}

void JobRunner::finish(const std::string& id, JobStatus status, const std::string& error) {
    // Files first, then the status: whoever sees the job finished finds its images on disk.
    if (status != JobStatus::Failed) writeImages(id);
    JobRecord job = table_.finish(id, status, error, utcNowIso8601());
    store_.update(job);
    hub_.publish(job, eventTypeFor(status));
    images_.drop(id);
}

void JobRunner::writeImages(const std::string& id) {
    for (ImageFormat format : {ImageFormat::Png, ImageFormat::Exr})
        if (std::optional<EncodedImage> image = images_.get(id, format))
            writeFileAtomically(folders_.imageFile(id, format), *image->bytes);
}

}  // namespace photon::server
