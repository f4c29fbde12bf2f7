// A pass band by band (render.bands): each band's camera paths, a grid over their discs, the
// pass's photons gathered into them, and then their results, which the statistics take
// while the next band is traced. Only the band's results and the two rows before it are
// held, not the frame's: 24 bytes a pixel less for the frame (docs/sppm.md, "Memory").
#include <algorithm>
#include <chrono>
#include "integrators/common/milliseconds_since.h"
#include "integrators/sppm/disc_coverage.h"
#include "integrators/sppm/sppm.h"
#include <tbb/parallel_for.h>

namespace photon {

bool SppmIntegrator::traceBands(const CancelToken& cancel, int64_t photons, const BandResults& onBand, bool commits) {
    allocatePassBuffers();
    photonsTraced_ = false;
    // Once a band has changed the render the pass must be added whole: the bands after it
    // are traced to their end whatever `cancel` says.
    const CancelToken goesOn;
    bool committed = false;
    for (bandFirstRow_ = 0; bandFirstRow_ < height_; bandFirstRow_ += bandRows_) {
        const CancelToken& stop = committed ? goesOn : cancel;
        if (bandFirstRow_ > 0) holdRows();
        bandOffset_ = static_cast<size_t>(bandFirstRow_) * width_;
        auto t0 = std::chrono::steady_clock::now();
        cameraPass(stop);
        stats_.cameraMs += millisecondsSince(t0);
        if (stop.cancelled()) return false;
        if (tracesPhotons_) {
            t0 = std::chrono::steady_clock::now();
            buildGrid();
            stats_.gridMs += millisecondsSince(t0);
            stats_.gridEntries += static_cast<int64_t>(grid_.entryCount());
            // A band where no camera path stored a visible point (all hair, or sky) gathers
            // nothing whatever photons it traces: its pass is the same without them, and
            // costs its camera paths alone (a tuft of hair under the sky: docs/sppm.md).
            if (grid_.entryCount() > 0) {
                t0 = std::chrono::steady_clock::now();
                // Unmarked, whatever a cancelled pass left (render.disc_coverage).
                if (coversDiscs_) std::fill(edgeSeen_.begin(), edgeSeen_.end(), uint8_t{0});
                photonPass(stop, photons);
                stats_.photonMs += millisecondsSince(t0);
                photonsTraced_ = true;
                if (stop.cancelled()) return false;
            }
        }
        collectBand();
        const int end = std::min(bandFirstRow_ + bandRows_, height_);
        // Before the last band's results: they end the pass, and may set the next one's count.
        if (end == height_ && photonsTraced_) stats_.photons = photons;
        onBand(bandFirstRow_, end, end == height_);
        committed = commits;
    }
    return true;
}

void SppmIntegrator::holdRows() {
    // Every band but the last holds bandRows_ rows, so the one before this ends at
    // results_' last kHeldRows rows (with bands of one row, the first of them was held).
    const size_t held = static_cast<size_t>(kHeldRows) * width_;
    std::copy(results_.end() - static_cast<std::ptrdiff_t>(held), results_.end(), results_.begin());
}

void SppmIntegrator::collectBand() {
    const double fluxUnit = scene_->lights().totalAveragePower() / kFluxScale;
    // The flux's rounding, from a stream of its own per pixel and pass: the same wherever
    // and in whatever band the pixel is.
    const RngStream rounding(settings_.seed, static_cast<uint64_t>(passIndex_), StreamPurpose::Rounding);
    const RngStream covering(settings_.seed, static_cast<uint64_t>(passIndex_), StreamPurpose::Coverage);
    tbb::parallel_for(size_t(0), bandPixels(), [&](size_t k) {
        const VisiblePoint& vp = visible_[k];
        PassResult& r = result(bandOffset_ + k);
        const Color flux(static_cast<float>(static_cast<double>(vp.flux[0]) * fluxUnit),
                         static_cast<float>(static_cast<double>(vp.flux[1]) * fluxUnit),
                         static_cast<float>(static_cast<double>(vp.flux[2]) * fluxUnit));
        r.photonCount = vp.photonCount();
        r.radiusSquared = discs_[k].radiusSquared;
        // A ball's photons spread as a volume's, which the disc's rule does not read.
        r.spread = vp.inMedium || guidePass_ >= 0 ? PhotonSpread::kUnknown : PhotonSpread::of(vp.high(), r.photonCount);
        // render.disc_coverage: where the pass's photons showed an edge, the flux over the
        // share of the disc photons can land on, and the spread read against a flat light's
        // over that share. Only where photons came: elsewhere the flux is 0 whatever the share.
        float share = 1;
        if (coversDiscs_ && edgeSeen_[k] && r.photonCount > 0 && !vp.inMedium && guidePass_ < 0) {
            const DiscCoverage coverage =
                measureDiscCoverage(*scene_, discs_[k].center, vp.n.decode(), discs_[k].radiusSquared, vp.transmits,
                                    settings_.kernel, Rng(covering, bandOffset_ + k).uniform());
            share = coverage.share;
            if (r.spread != PhotonSpread::kUnknown)
                r.spread = PhotonSpread::code(PhotonSpread::mean(r.spread) - coverage.meanSpread + 0.5f);
        }
        r.flux = SharedExponentColor::of(flux / share, Rng(rounding, bandOffset_ + k).uniform());
    });
}

void SppmIntegrator::buildGrid() {
    grid_.build(std::span<const GatherDisc>(discs_.data(), bandPixels()));
}

// The next band's camera paths read the moments and direct light of the row above it
// (LearnedLobeChoice::othersProbability, AdaptiveCameraPaths::pathsAt), so a band's last row
// is added to them only after the next band is traced; a pixel's radius reads its
// neighbours' moments (AdaptiveRadius::shrink), so it shrinks a row after them. Every read
// then sees what it would in one band, and the image is the same to the bit.
void SppmIntegrator::commitBand(int first, int end, bool last) {
    const auto t0 = std::chrono::steady_clock::now();
    {
        std::lock_guard<std::mutex> lock(stateMutex_);
        if (adaptivePhotons_) measurePhotonVariance(first, end);
        const int added = last ? end : end - 1, shrunk = last ? end : end - 2;
        addToStatistics(std::max(first - 1, 0), std::max(added, 0));
        shrinkRadii(std::max(first - 2, 0), std::max(shrunk, 0));
    }
    if (last) finishPass();
    stats_.updateMs += millisecondsSince(t0);
}

}  // namespace photon
