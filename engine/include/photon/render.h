// The engine's face: render a scene pass by pass with progress reports and cancellation,
// take snapshots, save and restore checkpoints. Nothing here knows of HTTP, jobs or files
// to write.
#pragma once
#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <optional>
#include <photon/image.h>
#include <photon/pass_sums.h>
#include <photon/pending_image.h>
#include <photon/progress.h>
#include <photon/scene_file.h>

namespace photon {

class Scene;
class Integrator;
class ErrorDecay;

class Renderer {
public:
    // Builds the scene (its acceleration structure, lights, camera) and the integrator its
    // render block names.
    explicit Renderer(SceneFile scene);
    // For the engine's own tests and tools, which build scenes themselves.
    explicit Renderer(std::shared_ptr<const Scene> scene);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    using ProgressFn = std::function<void(const RenderProgress&)>;
    // Renders until the scene's pass count, time limit or target error is reached, or
    // `cancel` is set, then frees what only a next pass would use (a later run() or
    // renderPass() allocates it again).
    // onPass runs on the rendering thread after every finished pass.
    RenderOutcome run(const CancelToken& cancel, const ProgressFn& onPass = {});
    // Renders one pass; false if cancelled (the image stays as after the last pass).
    bool renderPass(const CancelToken& cancel);

    // Independent passes (render.radius_schedule "global"; docs/sppm.md): renderPasses
    // renders passes first .. first + count - 1 of this render on their own, without adding
    // them (nullopt if cancelled, or if the render's passes are not independent); addPasses
    // adds a batch rendered here or by any other Renderer of the same scene. Batches add
    // exactly, in any order: N renderers give the image one gives.
    bool independentPasses() const;
    std::optional<PassSums> renderPasses(int64_t first, int count, const CancelToken& cancel);
    void addPasses(const PassSums& sums);
    // Whether the estimated error is at or below render.target_error (false without one).
    bool targetErrorReached() const;

    // The image after the passes done so far: denoised when render.denoise is on (the
    // filter runs on every call, so call it once per pass, not per client).
    Image snapshot() const;
    // The integrator's own image, never denoised.
    Image rawSnapshot() const;
    // snapshot() as the main image; with denoising on, also the layers "raw", "albedo" and
    // "normal" (the guides, when guided); with an error estimate, the layer "error" (its
    // heat map: film/pixel_errors.h), for formats that hold them.
    LayeredImage layers() const;
    // The same, filtered only when first asked for, with the scene's exposure (see
    // PendingImage).
    std::shared_ptr<const PendingImage> pendingLayers() const;
    // pendingLayers() of an image another Renderer of the same scene made (rawSnapshot() on
    // a render farm worker): this render's post filter and exposure applied to it.
    std::shared_ptr<const PendingImage> pendingLayersOf(Image raw) const;
    // The render's whole state after the last finished pass, and its restoration into a
    // new Renderer of the same scene: the passes that follow give the image an
    // uninterrupted render would have. Where the bytes go is the caller's business.
    void saveCheckpoint(std::ostream& out) const;
    void restoreCheckpoint(std::istream& in);
    const RenderProgress& progress() const { return progress_; }
    const Integrator& integrator() const { return *integrator_; }
    const Scene& scene() const { return *scene_; }

private:
    RenderOutcome runPasses(const CancelToken& cancel, const ProgressFn& onPass);
    // The error estimate after the passes so far: progress_.relativeError, passesToTarget
    // and the heat map's source.
    void updateErrorEstimate();

    std::shared_ptr<const Scene> scene_;
    std::unique_ptr<Integrator> integrator_;
    std::shared_ptr<const Denoiser> denoiser_;  // null when render.denoise is off
    RenderProgress progress_;
    std::shared_ptr<const PixelErrors> errors_;  // after the last pass; null without an estimate
    std::unique_ptr<ErrorDecay> errorDecay_;     // the rate the estimate falls at, measured
    double renderSeconds_ = 0;
    // The passes since the photons per pass last changed (render.adaptive_photons): their
    // mean time is what each pass left will take. Photon count -1: not yet seen (a new or
    // resumed render, whose passes so far all count).
    struct PassWindow {
        int64_t photons = -1;
        int passes = 0;
        double seconds = 0;
    } window_;
};

}  // namespace photon
