// Stochastic progressive photon mapping (Hachisuka & Jensen 2009), with the radius
// schedule of Knaus & Zwicker 2011's probabilistic formulation. Each pass: a camera pass
// finds one visible point per pixel, a hash grid is built over them, photons are traced
// and splatted into the visible points around their hits, and per-pixel statistics are
// updated. Photons are never stored, so memory does not grow with their number.
#pragma once
#include <algorithm>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>
#include <tbb/enumerable_thread_specific.h>
#include <photon/pass_sums.h>
#include "accel/hash_grid.h"
#include "integrators/common/checkpoint.h"
#include "integrators/common/pass_halves.h"
#include "integrators/common/photon_emitter.h"
#include "math/octahedral.h"
#include "math/rng.h"
#include "math/path_sampler.h"
#include "scene/scene.h"
#include "integrators/common/shading.h"
#include "integrators/integrator.h"
#include "integrators/sppm/adaptive_radius.h"
#include "integrators/sppm/camera_paths.h"
#include "integrators/sppm/lobe_choice.h"
#include "math/bfloat16.h"
#include "math/shared_exponent_color.h"
#include "integrators/sppm/photon_budget.h"

namespace photon {

class SppmIntegrator final : public Integrator {
public:
    explicit SppmIntegrator(std::shared_ptr<const Scene> scene);

    bool renderPass(const CancelToken& cancel) override;
    Image snapshot() const override;
    const PassStats& lastPassStats() const override { return stats_; }
    int passesDone() const override { return passes_; }
    size_t bytesPerPixel() const override;
    void saveState(std::ostream& out) const override;
    void restoreState(std::istream& in) override;
    bool independentPasses() const override { return global(); }
    std::optional<PassSums> renderPasses(int64_t first, int count, const CancelToken& cancel) override;
    void addPasses(const PassSums& sums) override;
    std::optional<PixelErrors> pixelErrors() const override;
    // When a render stops: the grid, the band's visible points, discs and pass results,
    // which a next pass allocates again.
    void releasePassBuffers() override;

    // Persistent per-pixel statistics (the paper's N, R, tau) plus summed direct light.
    struct PixelState {
        Color directSum;  // sum over passes of direct radiance at the camera path
        Color tau;        // flux accumulated within the current radius
        float n = 0;      // photon count N after the alpha reduction
        float r2 = 0;     // squared gather radius; 0 until the pixel first sees a surface
    };
    const PixelState& pixel(int x, int y) const { return pixels_[static_cast<size_t>(y) * width_ + x]; }
    // Photons gathered by each pixel in the last pass (M in the paper), for tests of a
    // render in one band (in bands, only the last band's rows are still held).
    uint32_t lastPhotonCount(int x, int y) const { return result(static_cast<size_t>(y) * width_ + x).photonCount; }
    // The squared radius each pixel gathered in during the last pass (0: no visible point),
    // as lastPhotonCount.
    float lastRadiusSquared(int x, int y) const { return result(static_cast<size_t>(y) * width_ + x).radiusSquared; }
    // The bands of rows a pass is rendered in (render.bands).
    int bandCount() const { return (height_ + bandRows_ - 1) / bandRows_; }

private:
    // The first non-specular vertex of a pixel's camera path in this pass: its position
    // and squared gather radius (0: no visible point). They live apart because photons
    // test many of those for every one they add to: a compact array keeps that test in
    // cache. The grid is built from this array as it is.
    using GatherDisc = HashGrid::Sphere;
    // Everything a photon needs once it is inside the disc, and what it adds to, in one
    // cache line: one memory access per accepted photon.
    // A point in a medium (inMedium, render.volume_photons) keeps wo (world space) in n,
    // the medium's index in material, and in beta the camera path's throughput over sigma_s
    // times 3 / (4 r): its photons, gathered in a ball, are then counted in the units of a
    // disc's (storeVolumePoint).
    struct alignas(64) VisiblePoint {
        OctahedralVector n;        // shading normal
        OctahedralVector woLocal;  // outgoing direction in the frame of n
        // Camera path throughput up to here; for a Lambertian point already multiplied by
        // its f = tint / pi, which then needs no eval() per photon.
        Color beta;
        Vec2 uv;                   // where on the surface, for the material's textures
        uint32_t material : 23 = 0;
        uint32_t lobes : 6 = kAllLobes;  // the material's lobes photons are gathered through
        uint32_t lambertian : 1 = 0;
        uint32_t transmits : 1 = 0;  // photons arriving on the far side count too
        uint32_t inMedium : 1 = 0;   // a point in a medium (above)
        // M, the photons gathered this pass, in the low 32 bits; in the high 32 bits, in the
        // render's passes the sum of their d^2 / r^2 (PhotonSpread, render.adaptive_radius),
        // in the photon guide's training passes what a photon reaching this point is worth to
        // the guide (guideWeight()). One atomic add counts a photon and its spread.
        uint64_t gathered = 0;
        uint64_t flux[3] = {0, 0, 0};  // Phi in fixed point, atomically added
        uint32_t photonCount() const { return static_cast<uint32_t>(gathered); }
        uint32_t high() const { return static_cast<uint32_t>(gathered >> 32); }
        void setGuideWeight(uint32_t w) { gathered = static_cast<uint64_t>(w) << 32; }
    };
    static_assert(sizeof(VisiblePoint) == 64);

    // What a pass leaves at each pixel for its statistics: 24 bytes a pixel, the colours in
    // 4 bytes each (dithered, so that the sums over passes keep no rounding bias:
    // math/shared_exponent_color.h), held for the band under way and the kHeldRows rows
    // before it (sppm_bands.cpp).
    struct PassResult {
        // The camera paths' direct light (their mean; lightweight: the path-traced light).
        SharedExponentColor direct;
        SharedExponentColor flux;  // Phi, the flux its photons brought, in the lights' units
        uint32_t photonCount = 0;  // M
        float radiusSquared = 0;   // the pass's gather radius; 0: no visible point
        // render.lobe_choice: the branch the path took at its first choice between a
        // diffuse base and other lobes, and the luminance of the direct light found before
        // it, in 4 bytes: only the learned probability reads them, which 16 bits of each serve.
        LobeChoiceRecord choice;
        // render.adaptive_camera_paths: the sum of the camera paths' luminances squared
        // (bfloat16, for the variance alone), and the paths beyond the first.
        uint16_t squares = 0;
        uint8_t extraPaths = 0;
        // render.adaptive_radius: its photons' mean d^2 / r^2 (PhotonSpread).
        uint8_t spread = PhotonSpread::kUnknown;
        int paths() const { return extraPaths + 1; }
    };
    static_assert(sizeof(PassResult) == 24);

    // Fixed-point scale for the photon flux sums: 2^32 units per unit of normalised flux
    // (photons start with a mean flux of 1), so sums are exact integers whatever the order
    // threads add them in, and the image is bit-identical for any thread count.
    static constexpr double kFluxScale = 4294967296.0;

    bool global() const { return settings_.radiusSchedule == RadiusSchedule::Global; }
    // What is done with a band's results once they are in: rows [first, end) of the band
    // just traced, `last` for the pass's last band. Results are read with result().
    using BandResults = std::function<void(int first, int end, bool last)>;
    // Renders pass passIndex_ (camera pass, grid, photon pass), band by band, each band's
    // results to onBand; false once cancelled. `commits`: onBand changes the render, so
    // once it has taken a band the pass goes on to its end whatever `cancel` says (a pass
    // is added whole or not at all; with one band, onBand is called once, at the end).
    bool traceOnePass(const CancelToken& cancel, const BandResults& onBand, bool commits);
    // The pass's camera paths and `photons` photons, band by band (sppm_bands.cpp). Every
    // band traces the same photons, so each pixel's result is what one band would make.
    bool traceBands(const CancelToken& cancel, int64_t photons, const BandResults& onBand, bool commits);
    // The band's visible points into its results.
    void collectBand();
    // Before a band after the first: the last kHeldRows rows of the one before move to the
    // front of results_.
    void holdRows();
    // The per-pixel schedule's statistics take a band's results. A pixel's statistics read
    // its neighbours' moments, and its camera paths read theirs, so they go a row and two
    // rows behind the band (sppm_bands.cpp).
    void commitBand(int first, int end, bool last);
    // Rows [first, end)'s pass results into their moments, direct light and start radius.
    void addToStatistics(int first, int end);
    // Rows [first, end)'s photons into N, R and tau, their neighbours' moments added.
    void shrinkRadii(int first, int end);
    // Once every pixel has its pass: the pass is counted and the counts adapt to its error.
    void finishPass();
    // Sizes the visible points, discs and pass results if releasePassBuffers freed them.
    void allocatePassBuffers();
    // Frames above kOneBandPixels render in bands of at most kBandPixels (render.bands "auto").
    static constexpr size_t kOneBandPixels = size_t(1) << 22, kBandPixels = size_t(1) << 20;
    int rowsPerBand() const;
    // The global schedule's r_i^2 / r_1^2 for the pass with index i (from 0).
    double globalShrinkAt(int64_t i) const;
    // Pixel i's estimate from this pass alone, direct + Phi / (pi r_i^2 N_emitted).
    Color passEstimate(size_t i) const;
    // Its photons' part, Phi / (pi r_i^2 N_emitted); none where the pixel gathered none.
    std::optional<Color> passPhotonEstimate(size_t i) const;
    // Adds the estimates of this pass's rows [first, end) to `sums` in fixed point (and their
    // luminance to its odd half for an odd pass), and at its `last` band counts the pass
    // there; throws std::invalid_argument, the sums then spent, where they would overflow.
    void addBandEstimate(PassSums& sums, int first, int end, bool last) const;
    // The global schedule's pass `index`: its radius, camera and photon passes, each band's
    // estimates added to `sums` (the render's own: `commits`).
    bool traceGlobalPass(int64_t index, const CancelToken& cancel, PassSums& sums, bool commits);
    Image snapshotLocked() const;
    // Pixel i of the per-pixel schedule's image.
    Color radianceLocked(size_t i) const;
    void cameraPass(const CancelToken& cancel);
    // Clears the pixel's visible point and returns a camera ray of it, with its weight.
    Camera::PixelSample startPixel(size_t index, PathSampler& sampler);
    // The numbers of camera path `path` of pixel `index` in this pass (render.sampler);
    // `rng` is the pixel's stream.
    PathSampler pathSampler(size_t index, Rng& rng, int path) const;
    // A camera ray of pixel `index`, drawn from the pixel filter, with its weight.
    Camera::PixelSample cameraRay(size_t index, PathSampler& sampler) const;
    // What a pixel's camera paths did in a pass.
    struct CameraWork {
        int rays = 0, paths = 0;
    };
    // Each returns the rays it cast (render.adaptive_photons' measure of the camera's cost).
    CameraWork tracePixel(size_t index, Rng& rng);
    // One camera path from the camera sample: adds the light it finds to `direct` and its first lobe
    // choice to `choice`; the first path of a pixel's pass (`first`) stores its visible
    // point. Returns the rays it cast.
    int tracePath(size_t index, const Camera::PixelSample& start, PathSampler& sampler, bool first, Color& direct,
                  LobeChoiceRecord& choice);
    // render.lightweight's camera path: a path-traced sample that leaves out the caustics
    // its visible point's photons bring (sppm_lightweight_camera_pass.cpp).
    int tracePixelLightweight(size_t index, Rng& rng);
    float autoRadius(float pathLength, bool inMedium) const;
    // With adaptive_radius, how wide a disc may start where fewer photons would be in it
    // (autoRadius).
    static constexpr float kFlatDiscPixels = 2.5f, kFlatPhotons = 64;
    void storeVisiblePoint(size_t index, const ShadingPoint& sp, Vec3 wo, Color beta, unsigned lobes, float pathLength);
    // A visible point where the first camera path scatters in `medium` at p, beta its
    // throughput with the flight's weight (render.volume_photons).
    // `behind`, `ahead`: the planes of the medium's boundary the path crossed last and of
    // the one its ray would have reached (PathInMedia), at infinity where there are none.
    void storeVolumePoint(size_t index, Vec3 p, Vec3 wo, Color beta, int32_t medium, float pathLength,
                          const CuttingPlane& behind, const CuttingPlane& ahead);
    // The medium a camera path goes on in from `hit` toward d, and the boundary it starts on.
    static void leaveSurface(const Scene& scene, const SurfaceHit& hit, Vec3 d, int32_t& medium, PathInMedia& inMedia);
    // The pixel's squared gather radius for this pass, from its statistics or (first pass,
    // guide training, global schedule) its footprint at `pathLength`; a ball's in a medium
    // of mean `extinction` > 0.
    float passRadiusSquared(size_t index, float pathLength, float extinction = 0) const;
    // Whether photons are gathered where they scatter in media, at the camera paths' first
    // scattering there (render.volume_photons, in a scene with media that scatter).
    bool gathersInMedia() const { return gathersInMedia_; }
    static bool gathersInMedia(const Scene& scene);
    static float smoothDielectricReflectance(const Material& m, Vec3 woLocal);
    // Traces the BSDF sample s from sp and adds to `direct` the light it finds, weighted
    // against the vertex's light sample; `at` is its hit as cast, `medium` the one the path
    // reached it in. Returns whether it cast the ray: not where no light lies along it
    // (Scene::mayFindLight).
    static bool lookUpLight(const Scene& scene, const SurfaceHit& at, const ShadingPoint& sp, const BSDFSample& s,
                            Color beta, int32_t medium, Color& direct);
    void buildGrid();
    void photonPass(const CancelToken& cancel, int64_t photons);
    // render.photon_guiding (sppm_guide_training.cpp): before the first pass, kGuidePasses
    // passes of their own random streams teach the guide, which then stays as it is, so
    // that every pass after them is drawn alike and independent of the others (the global
    // schedule's passes too), and the guide is the same wherever the render resumes.
    static constexpr int kGuidePasses = 4;
    // Photons a training pass traces: enough that a cell's worth is known from hundreds of
    // its photons, not the few that a pass of the render's would give it.
    int64_t guidePhotonsPerPass() const;
    bool trainGuide(const CancelToken& cancel);
    // A photon reaching pixel i's visible point is worth 1 / (1 + M) to the guide, M the
    // photons the pixel gathered in an average training pass so far, in units of 2^-16: a
    // photon for a pixel short of them counts more than one more for a pixel that has plenty.
    uint32_t guideWeight(size_t index) const;
    // The guide learns what a training pass's photons reached.
    void teachGuide();
    struct PhotonCounters {
        int64_t rays = 0, segments = 0, candidates = 0, accepted = 0;
        uint64_t* guideWorth = nullptr;  // this thread's guideWeight() sums, by guide cell
    };
    // A photon's arrival on a non-delta surface, waiting to be added to visible points.
    struct PhotonHit {
        // Position, shading normal (0 where the photon scattered in a medium), direction back
        // toward the photon's origin.
        Vec3 p, n, wi;
        Color flux;
        uint32_t cell;  // the emission guide's cell the photon left from
    };
    // Photon hits reach their visible points through a pipeline of batches, so that the
    // memory each step needs (grid bucket, entries, discs, visible points) is fetched well
    // before it is used (sppm_gather_pipeline.h).
    class GatherPipeline;
    class GatheringSink;
    void addPhoton(const PhotonHit& hit, uint32_t point, float d2OverR2, PhotonCounters& counters);
    // After a pass's statistics: with render.adaptive_photons what the pass measured goes to
    // the budget, which at its decisions sets the photons of the passes that follow; with
    // render.adaptive_camera_paths the camera paths' scale is set at the same decisions.
    void adaptToError();
    // Rows [first, end)'s sums of p^2 / M, each row's in a fixed order, into rowVariance_.
    void measurePhotonVariance(int first, int end);
    // The mean over pixels of p^2 / M, the variance this pass's photons brought given its
    // camera paths (photon_budget.h), summed row by row: the same in any band count.
    double photonVarianceOfPass() const;
    // The key of this render's checkpoints, with adaptive or fixed photon counts.
    CheckpointKey checkpointKeyWith(bool adaptivePhotons) const;

    std::shared_ptr<const Scene> scene_;
    const RenderSettings& settings_;
    PhotonEmitter emitter_;
    int width_, height_;
    int passes_ = 0;
    int64_t passIndex_ = 0;     // the pass being rendered: its random streams' index
    int64_t photons_;           // photons the pass being rendered traces
    int64_t emitted_ = 0;       // photons the per-pixel schedule's counted passes traced
    PhotonBudget budget_;       // render.adaptive_photons' measurements
    // Whether the photons per pass follow the error (adaptsPhotonsPerPass), unless resumed
    // from a checkpoint written with fixed counts.
    bool adaptivePhotons_;
    float globalShrink_ = 1;    // the global schedule's r_i^2 / r_1^2 for that pass
    bool tracesPhotons_ = true; // false: passes are camera passes alone (sppm.cpp)
    bool gathersInMedia_;
    PassStats stats_;
    bool photonsTraced_ = false;  // the pass traced photons for at least one band

    std::vector<PixelState> pixels_;  // the per-pixel schedule's statistics
    PassSums sums_;                    // the global schedule's: its passes' estimates summed
    bool sumsHalfKnown_ = true;        // false once resumed from a checkpoint without the odd half
    // The per-pixel schedule's passes' own estimates, summed in halves for the error
    // estimate: their spread tracks the noise of the progressive estimate, whose radius
    // shrinks as the global schedule's does (checked against two seeds in the tests).
    PassHalves halves_;
    LightsInView lightsInView_;  // the lights each pixel shows, for the error estimate
    // render.lobe_choice "learned" (learnsLobeChoice): each pixel's moments of its choices.
    bool learnsLobeChoice_;
    LearnedLobeChoice lobeChoice_;
    // render.adaptive_camera_paths (adaptsCameraPaths): the camera paths per pixel and pass.
    bool adaptsCameraPaths_;
    AdaptiveCameraPaths cameraPaths_;
    // render.adaptive_radius (adaptsRadius): each pixel's moments of its photons' spread.
    bool adaptsRadius_;
    AdaptiveRadius radius_;
    // render.disc_coverage (coversDiscs): each visible point's disc measured (disc_coverage.h).
    bool coversDiscs_;
    // The camera paths pixel i's direct light sum was made of.
    float directPaths(size_t i) const {
        return adaptsCameraPaths_ ? cameraPaths_.pathsTraced(i) : static_cast<float>(passes_);
    }
    // The band under way: its rows [bandFirstRow_, bandFirstRow_ + bandRows_) (fewer in the
    // last band), whose pixel i is at discs_ and visible_ [i - bandOffset_].
    int bandRows_ = 1;
    int bandFirstRow_ = 0;
    size_t bandOffset_ = 0;
    size_t bandPixels() const {
        return static_cast<size_t>(std::min(bandRows_, height_ - bandFirstRow_)) * static_cast<size_t>(width_);
    }
    std::vector<GatherDisc> discs_;
    std::vector<VisiblePoint> visible_;
    // render.disc_coverage: 1 where a band pixel's disc turned away a photon this pass (a
    // surface facing elsewhere inside its sphere: an edge), so that its coverage is measured
    // in full (collectBand).
    std::vector<uint8_t> edgeSeen_;
    // The pass's results of the band's rows and of the kHeldRows rows before it, whose
    // statistics wait for the band (commitBand): pixel i's at results_[i + kHeldRows * width_
    // - bandOffset_]. Two rows of a 3840-pixel frame are 184 KB; the frame's were 199 MB.
    static constexpr int kHeldRows = 2;
    std::vector<PassResult> results_;
    PassResult& result(size_t pixel) { return results_[pixel + kHeldRows * static_cast<size_t>(width_) - bandOffset_]; }
    const PassResult& result(size_t pixel) const {
        return results_[pixel + kHeldRows * static_cast<size_t>(width_) - bandOffset_];
    }
    std::vector<double> rowVariance_;  // measurePhotonVariance's, a row each
    HashGrid grid_;
    // render.photon_guiding: where photons leave the lights; while it is trained, each
    // thread's sums of what the pass's photons were worth, and the photons each pixel has
    // gathered in the training passes so far.
    std::optional<EmissionGuide> guide_;
    int guidePass_ = -1;  // the training pass under way, or -1
    tbb::enumerable_thread_specific<std::vector<uint64_t>> guideWorth_;
    std::vector<uint32_t> guidePhotons_;
    mutable std::mutex stateMutex_;      // guards pixels_ and passes_ between update and snapshot
};

}  // namespace photon
