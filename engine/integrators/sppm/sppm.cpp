// SPPM: construction, the per-pass driver, the statistics update and snapshots.
#include "integrators/sppm/sppm.h"
#include "integrators/common/checkpoint.h"
#include <tbb/parallel_for.h>
#include <atomic>
#include <cmath>
#include <stdexcept>

namespace photon {

namespace {
// Luminance in the pass sums' fixed point, from the fixed-point channels themselves, so
// that it is exact and the same wherever the pass was rendered.
int64_t fixedLuminance(const int64_t* rgb) {
    return std::llround(0.2126 * static_cast<double>(rgb[0]) + 0.7152 * static_cast<double>(rgb[1]) +
                        0.0722 * static_cast<double>(rgb[2]));
}
}  // namespace

SppmIntegrator::SppmIntegrator(std::shared_ptr<const Scene> scene)
    : scene_(std::move(scene)), settings_(scene_->settings()), emitter_(*scene_, settings_.projectionMaps),
      width_(scene_->camera().width()), height_(scene_->camera().height()), photons_(settings_.photonsPerPass),
      adaptivePhotons_(adaptsPhotonsPerPass(settings_)), gathersInMedia_(gathersInMedia(*scene_)),
      halves_(global() ? 0 : static_cast<size_t>(width_) * height_), lightsInView_(*scene_),
      learnsLobeChoice_(learnsLobeChoice(settings_)),
      adaptsCameraPaths_(adaptsCameraPaths(settings_)), adaptsRadius_(adaptsRadius(settings_)),
      coversDiscs_(coversDiscs(settings_)) {
    if (learnsLobeChoice_) lobeChoice_ = LearnedLobeChoice(width_, height_);
    if (adaptsRadius_) radius_ = AdaptiveRadius(width_, height_);
    if (adaptsCameraPaths_) cameraPaths_ = AdaptiveCameraPaths(width_, height_);
    size_t n = static_cast<size_t>(width_) * height_;
    if (global()) {
        sums_.width = width_, sums_.height = height_;
        sums_.values.assign(n * 3, 0);
        sums_.oddLuminance.assign(n, 0);
    } else {
        pixels_.resize(n);
    }
    bandRows_ = rowsPerBand();
    rowVariance_.assign(static_cast<size_t>(height_), 0.0);
    allocatePassBuffers();
    // Lightweight photon mapping's photons arrive only after a delta bounce: with no
    // material that has one, none would, and the path tracer has all the light.
    if (settings_.lightweight) {
        tracesPhotons_ = false;
        for (const MaterialPtr& m : scene_->description().materials) tracesPhotons_ |= (m->lobes() & kDeltaLobe) != 0;
    }
    if (settings_.photonGuiding && tracesPhotons_ && scene_->lights().size() > 0) guide_.emplace(scene_->lights());
}

bool SppmIntegrator::gathersInMedia(const Scene& scene) {
    const VolumePhotons setting = scene.settings().volumePhotons;
    if (!scene.hasScatteringMedia() || setting == VolumePhotons::Never) return false;
    if (setting == VolumePhotons::Always) return true;
    // Auto: only a surface with a delta lobe sends light into a medium along paths that no
    // light sample finds (a point light's through glass, a mirror's). Elsewhere the camera
    // path's light samples at each of its scattering points find all of the light, with no
    // ball cut by the medium's boundary (docs/sppm.md, "Volume photons").
    for (uint32_t i = 0; i < scene.shapeCount(); ++i)
        if (!scene.passesThrough(i) && (scene.materialAt(scene.shape(i).material).lobes() & kDeltaLobe)) return true;
    return false;
}

int SppmIntegrator::rowsPerBand() const {
    const size_t pixels = static_cast<size_t>(width_) * height_;
    int bands = settings_.bands;
    if (bands <= 0) bands = pixels <= kOneBandPixels ? 1 : static_cast<int>((pixels + kBandPixels - 1) / kBandPixels);
    bands = std::clamp(bands, 1, std::max(height_, 1));
    return std::max((height_ + bands - 1) / bands, 1);
}

void SppmIntegrator::allocatePassBuffers() {
    if (!results_.empty()) return;
    const size_t band = static_cast<size_t>(bandRows_) * width_;
    discs_.resize(band);
    visible_.resize(band);
    if (coversDiscs_) edgeSeen_.assign(band, 0);
    results_.resize(static_cast<size_t>(bandRows_ + kHeldRows) * width_);
}

void SppmIntegrator::releasePassBuffers() {
    grid_.release();
    // Assigned empty vectors, which take their storage with them (= {} would only clear).
    discs_ = std::vector<GatherDisc>();
    visible_ = std::vector<VisiblePoint>();
    edgeSeen_ = std::vector<uint8_t>();
    results_ = std::vector<PassResult>();
}

size_t SppmIntegrator::bytesPerPixel() const {
    const size_t state = global() ? 4 * sizeof(int64_t)
                         : sizeof(PixelState) + 2 * sizeof(float) +
                               (learnsLobeChoice_ ? LearnedLobeChoice::kBytesPerPixel : 0) +
                               (adaptsCameraPaths_ ? AdaptiveCameraPaths::kBytesPerPixel : 0) +
                               (adaptsRadius_ ? AdaptiveRadius::kBytesPerPixel : 0);
    const size_t band = (sizeof(GatherDisc) + sizeof(VisiblePoint) + sizeof(PassResult) +
                         (coversDiscs_ ? sizeof(uint8_t) : 0)) *
                        static_cast<size_t>(bandRows_ + kHeldRows) / static_cast<size_t>(std::max(height_, 1));
    const size_t pixels = static_cast<size_t>(width_) * static_cast<size_t>(std::max(height_, 1));
    return state + lightsInView_.bytes() / std::max<size_t>(pixels, 1) + band;
}

bool SppmIntegrator::renderPass(const CancelToken& cancel) {
    // Added straight into the render's sums, not through a batch of one pass: a batch is
    // 32 bytes a pixel more at the peak (212 MiB for a 3840 x 2160 frame).
    if (global()) return traceGlobalPass(passes_, cancel, sums_, true);
    passIndex_ = passes_;
    return traceOnePass(cancel, [&](int first, int end, bool last) { commitBand(first, end, last); }, true);
}

// Knaus & Zwicker 2011, eq. 15: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) for passes counted
// from 1, so r_i^2 / r_1^2 = prod_{k=1}^{i-1} (k + alpha) / (k + 1)
// = Gamma(i + alpha) / (Gamma(1 + alpha) Gamma(i + 1)), by lgamma for any i in constant time.
double SppmIntegrator::globalShrinkAt(int64_t index) const {
    const double i = static_cast<double>(index) + 1.0, a = settings_.alpha;
    return std::exp(std::lgamma(i + a) - std::lgamma(1.0 + a) - std::lgamma(i + 1.0));
}

std::optional<PassSums> SppmIntegrator::renderPasses(int64_t first, int count, const CancelToken& cancel) {
    if (!global() || first < 0 || count <= 0) return std::nullopt;
    PassSums batch;
    batch.first = first;
    batch.width = width_, batch.height = height_;
    batch.values.assign(static_cast<size_t>(width_) * height_ * 3, 0);
    batch.oddLuminance.assign(static_cast<size_t>(width_) * height_, 0);
    for (int k = 0; k < count; ++k)
        if (!traceGlobalPass(first + k, cancel, batch, false)) return std::nullopt;
    return batch;
}

bool SppmIntegrator::traceGlobalPass(int64_t index, const CancelToken& cancel, PassSums& sums, bool commits) {
    passIndex_ = index;
    globalShrink_ = static_cast<float>(globalShrinkAt(passIndex_));
    double radiusSum = 0;
    size_t withRadius = 0;
    auto onBand = [&](int first, int end, bool last) {
        for (size_t i = static_cast<size_t>(first) * width_; i < static_cast<size_t>(end) * width_; ++i)
            if (const float r2 = result(i).radiusSquared; r2 > 0) radiusSum += std::sqrt(r2), ++withRadius;
        std::unique_lock<std::mutex> lock(stateMutex_, std::defer_lock);
        if (commits) lock.lock();
        addBandEstimate(sums, first, end, last);
        if (commits) passes_ = static_cast<int>(sums_.count);
    };
    if (!traceOnePass(cancel, onBand, commits)) return false;
    stats_.meanRadius = withRadius ? radiusSum / static_cast<double>(withRadius) : 0.0;
    return true;
}

void SppmIntegrator::addPasses(const PassSums& batch) {
    if (!global()) Integrator::addPasses(batch);
    std::lock_guard<std::mutex> lock(stateMutex_);
    sums_.add(batch);
    passes_ = static_cast<int>(sums_.count);
}

// One pass's estimate per pixel: the direct light its camera path found plus the photons'
// flux within the pass's radius, Phi / (pi r_i^2 N_emitted) (Knaus & Zwicker 2011, eq. 11).
Color SppmIntegrator::passEstimate(size_t i) const {
    Color L = result(i).direct.color();
    if (std::optional<Color> photons = passPhotonEstimate(i)) L += *photons;
    return L;
}

std::optional<Color> SppmIntegrator::passPhotonEstimate(size_t i) const {
    const PassResult& r = result(i);
    if (r.photonCount == 0 || !(r.radiusSquared > 0)) return std::nullopt;
    const double emitted = static_cast<double>(photons_);
    const double toRadiance = 1.0 / (kPi * static_cast<double>(r.radiusSquared) * emitted);
    const Color flux = r.flux.color();
    return Color(static_cast<float>(static_cast<double>(flux[0]) * toRadiance),
                 static_cast<float>(static_cast<double>(flux[1]) * toRadiance),
                 static_cast<float>(static_cast<double>(flux[2]) * toRadiance));
}

void SppmIntegrator::addBandEstimate(PassSums& sums, int first, int end, bool last) const {
    const bool odd = passIndex_ & 1;
    std::atomic<bool> overflow = false;
    tbb::parallel_for(static_cast<size_t>(first) * width_, static_cast<size_t>(end) * width_, [&](size_t i) {
        const Color L = passEstimate(i);
        int64_t pass[3];
        bool over = false;
        for (int c = 0; c < 3; ++c) {
            pass[c] = std::llround(static_cast<double>(std::max(L[c], 0.0f)) * PassSums::kScale);
            over |= __builtin_add_overflow(sums.values[i * 3 + c], pass[c], &sums.values[i * 3 + c]);
        }
        if (odd) over |= __builtin_add_overflow(sums.oddLuminance[i], fixedLuminance(pass), &sums.oddLuminance[i]);
        if (over) overflow = true;
    });
    // As PassSums::add: past 10^6 passes of a radiance of 5 * 10^5 the render cannot go on.
    if (overflow) throw std::invalid_argument("pass sums overflow");
    if (!last) return;
    ++sums.count;
    sums.oddCount += odd;
}

bool SppmIntegrator::traceOnePass(const CancelToken& cancel, const BandResults& onBand, bool commits) {
    if (guide_ && !guide_->trained() && !trainGuide(cancel)) return false;
    stats_ = PassStats{};
    return traceBands(cancel, photons_, onBand, commits);
}

// Hachisuka & Jensen 2009, eq. 7-10: N' = N + alpha M, R'^2 = R^2 (N + alpha M)/(N + M),
// tau' = (tau + Phi) R'^2 / R^2. Photon fluxes were normalised to a mean of 1, so Phi is
// scaled back by the lights' total power here.
void SppmIntegrator::addToStatistics(int first, int end) {
    tbb::parallel_for(static_cast<size_t>(first) * width_, static_cast<size_t>(end) * width_, [&](size_t i) {
        const PassResult& r = result(i);
        const float passLuminance = luminance(passEstimate(i));
        halves_.add(passIndex_, i, passLuminance);
        if (learnsLobeChoice_ && r.choice.made())
            lobeChoice_.add(i, r.choice.others(), r.choice.probability(),
                            std::max(passLuminance - r.choice.directBeforeChoice(), 0.0f));
        if (adaptsCameraPaths_) cameraPaths_.add(i, static_cast<float>(r.paths()), fromBfloat16(r.squares));
        PixelState& px = pixels_[i];
        if (adaptsRadius_) radius_.add(i, r.photonCount, r.spread, r.radiusSquared);
        px.directSum += r.direct.color() * static_cast<float>(r.paths());  // the pass's is its paths' mean
        if (px.r2 == 0) px.r2 = r.radiusSquared;  // first pass with a visible point sets the start radius
    });
}

void SppmIntegrator::shrinkRadii(int first, int end) {
    tbb::parallel_for(static_cast<size_t>(first) * width_, static_cast<size_t>(end) * width_, [&](size_t i) {
        PixelState& px = pixels_[i];
        const PassResult& r = result(i);
        const float m = static_cast<float>(r.photonCount);
        if (m == 0 || px.r2 == 0) return;
        float nNew, shrink;
        if (adaptsRadius_) {
            shrink = radius_.shrink(i, px.n, m, px.r2, settings_.alpha);
            nNew = (px.n + m) * shrink;
        } else {
            nNew = px.n + settings_.alpha * m;
            shrink = nNew / (px.n + m);
        }
        px.tau = (px.tau + r.flux.color()) * shrink;
        px.r2 *= shrink;
        px.n = nNew;
    });
}

void SppmIntegrator::finishPass() {
    std::lock_guard<std::mutex> lock(stateMutex_);
    halves_.countPass(passIndex_);
    if (learnsLobeChoice_) lobeChoice_.countPass();
    ++passes_;
    emitted_ += photons_;
    if (adaptivePhotons_ || adaptsCameraPaths_) adaptToError();
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
    writeCheckpointHeader(out, checkpointKeyWith(adaptivePhotons_));
    writeRaw(out, &passes_, 1);
    if (global()) {
        writeRaw(out, sums_.values.data(), sums_.values.size());
        if (sumsHalfKnown_) {  // the odd half, which checkpoints written before it lack
            writeRaw(out, &sums_.oddCount, 1);
            writeRaw(out, sums_.oddLuminance.data(), sums_.oddLuminance.size());
        }
    } else {
        writeRaw(out, pixels_.data(), pixels_.size());
        if (adaptivePhotons_) {
            writeRaw(out, &photons_, 1);
            writeRaw(out, &emitted_, 1);
            budget_.save(out);
        }
        if (learnsLobeChoice_) lobeChoice_.save(out);
        if (adaptsCameraPaths_) cameraPaths_.save(out);
        if (adaptsRadius_) radius_.save(out);
        halves_.save(out);
    }
}

void SppmIntegrator::restoreState(std::istream& in) {
    // A checkpoint written with fixed photon counts (before adaptive counts were the
    // default, or with them off) goes on with fixed counts.
    const bool writtenFixed = readCheckpointHeader(in, checkpointKeyWith(adaptivePhotons_), checkpointKeyWith(false));
    const bool adaptive = adaptivePhotons_ && !writtenFixed;
    int passes = readPassCount(in);
    if (global()) {
        std::vector<int64_t> values(sums_.values.size());
        readRaw(in, values.data(), values.size());
        for (int64_t v : values)
            if (v < 0) throw CheckpointError("checkpoint: invalid pass sums");
        int64_t oddCount = 0;
        std::vector<int64_t> odd(sums_.oddLuminance.size(), 0);
        const bool halfKnown = in.peek() != std::char_traits<char>::eof();
        in.clear();
        if (halfKnown) {
            readRaw(in, &oddCount, 1);
            readRaw(in, odd.data(), odd.size());
            if (oddCount < 0 || oddCount > passes) throw CheckpointError("checkpoint: invalid pass sums");
            for (int64_t v : odd)
                if (v < 0) throw CheckpointError("checkpoint: invalid pass sums");
        }
        requireEndOfCheckpoint(in);
        std::lock_guard<std::mutex> lock(stateMutex_);
        passes_ = passes;
        sums_.values = std::move(values);
        sums_.count = passes;
        sums_.oddCount = oddCount;
        sums_.oddLuminance = std::move(odd);
        sumsHalfKnown_ = halfKnown;
        return;
    }
    std::vector<PixelState> pixels(pixels_.size());
    readRaw(in, pixels.data(), pixels.size());
    for (const PixelState& p : pixels)
        if (!isFiniteNonNegative(p.directSum) || !isFiniteNonNegative(p.tau) || !isFiniteNonNegative(p.n) ||
            !isFiniteNonNegative(p.r2))
            throw CheckpointError("checkpoint: invalid pixel statistics");
    int64_t photons = settings_.photonsPerPass, emitted = passes * settings_.photonsPerPass;
    PhotonBudget budget;
    if (adaptive) {
        readRaw(in, &photons, 1);
        readRaw(in, &emitted, 1);
        // Counts no render could have reached: a damaged checkpoint must not start a pass of
        // 2^60 photons.
        const PhotonBudget::Range range = PhotonBudget::reachable(settings_.photonsPerPass, passes);
        const double passCount = static_cast<double>(passes);
        if (photons < std::max<int64_t>(range.lo, 1) || photons > range.hi || emitted < 0 ||
            static_cast<double>(emitted) > passCount * static_cast<double>(range.hi))
            throw CheckpointError("checkpoint: invalid photon counts");
        budget.restore(in);
    }
    LearnedLobeChoice lobeChoice = lobeChoice_;
    if (learnsLobeChoice_) lobeChoice.restore(in, passes);
    AdaptiveCameraPaths cameraPaths = cameraPaths_;
    if (adaptsCameraPaths_)
        cameraPaths.restore(in, passes, [&](size_t i) { return luminance(pixels[i].directSum); });
    AdaptiveRadius radius = radius_;
    if (adaptsRadius_) radius.restore(in);
    std::lock_guard<std::mutex> lock(stateMutex_);
    halves_.restore(in, passes);  // last: it checks the end, and commits only if all is well
    lobeChoice_ = std::move(lobeChoice);
    radius_ = std::move(radius);
    cameraPaths_ = std::move(cameraPaths);
    passes_ = passes;
    pixels_ = std::move(pixels);
    photons_ = photons;
    emitted_ = emitted;
    budget_ = budget;
    adaptivePhotons_ = adaptive;
}

CheckpointKey SppmIntegrator::checkpointKeyWith(bool adaptivePhotons) const {
    RenderSettings settings = settings_;
    settings.adaptivePhotons = adaptivePhotons;
    return checkpointKey(settings, width_, height_);
}

// L = direct / passes + tau / (pi R^2 N_emitted) (Hachisuka & Jensen 2009, eq. 12).
Image SppmIntegrator::snapshot() const {
    std::lock_guard<std::mutex> lock(stateMutex_);
    return snapshotLocked();
}

std::optional<PixelErrors> SppmIntegrator::pixelErrors() const {
    std::lock_guard<std::mutex> lock(stateMutex_);
    const double decay = settings_.alpha / 2;  // film/pixel_errors.h
    if (!global())
        return halves_.errors(width_, height_, [&](size_t i) { return radianceLocked(i); }, lightsInView_, decay);
    if (!sumsHalfKnown_) return std::nullopt;
    const double passes = static_cast<double>(std::max<int64_t>(passes_, 1));
    auto all = [&](size_t i) { return static_cast<double>(fixedLuminance(&sums_.values[3 * i])); };
    return pixelErrorsOf(
        width_, height_, [&](size_t i) { return static_cast<float>(all(i) / (PassSums::kScale * passes)); },
        [&](size_t i) {
            const double odd = static_cast<double>(sums_.oddLuminance[i]);
            return halfSplitVariance(odd / PassSums::kScale, (all(i) - odd) / PassSums::kScale, sums_.oddCount,
                                     sums_.count - sums_.oddCount);
        },
        lightsInView_.light(), decay);
}

// Knaus & Zwicker 2011: the mean of the passes' direct light (over all camera paths, where
// pixels trace several a pass) plus tau / (pi R^2 N_emitted).
Color SppmIntegrator::radianceLocked(size_t i) const {
    if (passes_ == 0) return Color(0.0f);
    const double emitted = static_cast<double>(emitted_);
    const PixelState& px = pixels_[i];
    Color L = px.directSum * (1.0f / directPaths(i));
    if (px.r2 > 0) L += px.tau * static_cast<float>(1.0 / (kPi * px.r2 * emitted));
    return L;
}

Image SppmIntegrator::snapshotLocked() const {
    Image image(width_, height_);
    if (passes_ == 0) return image;
    if (global()) {  // the mean of the passes' estimates
        const double unit = 1.0 / (PassSums::kScale * static_cast<double>(passes_));
        tbb::parallel_for(0, height_, [&](int y) {
            for (int x = 0; x < width_; ++x) {
                const int64_t* v = &sums_.values[(static_cast<size_t>(y) * width_ + x) * 3];
                image.set(x, y, Color(static_cast<float>(static_cast<double>(v[0]) * unit),
                                      static_cast<float>(static_cast<double>(v[1]) * unit),
                                      static_cast<float>(static_cast<double>(v[2]) * unit)));
            }
        });
        return image;
    }
    tbb::parallel_for(0, height_, [&](int y) {
        for (int x = 0; x < width_; ++x) image.set(x, y, radianceLocked(static_cast<size_t>(y) * width_ + x));
    });
    return image;
}

}  // namespace photon
