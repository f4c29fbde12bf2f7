// Luminance summed per pixel over a render's odd-numbered and even-numbered passes apart:
// what the error estimate (film/pixel_errors.h) reads for integrators that keep their
// image in floating point (the path tracer, radiosity's camera pass, SPPM with per-pixel
// radii). 8 bytes a pixel: floats, whose rounding over N passes stays below N * 6e-8 of a
// half's sum (6e-4 after 10^4 passes, and sqrt(N) * 6e-8 typically), far below any error
// a render would be stopped at. SPPM with the global schedule keeps its odd half in PassSums
// instead, in fixed point, so that batches from a farm add exactly.
#pragma once
#include <istream>
#include <optional>
#include <ostream>
#include <vector>
#include <photon/image.h>
#include "film/pixel_errors.h"
#include "integrators/common/lights_in_view.h"

namespace photon {

class PassHalves {
public:
    explicit PassHalves(size_t pixels) : sums_(2 * pixels, 0.0f) {}
    // Adds pass `pass`'s luminance at `pixel`; thread-safe across pixels.
    void add(int64_t pass, size_t pixel, float luminance) { sums_[2 * pixel + (pass & 1)] += luminance; }
    // Counts pass `pass` as added (once per pass, after its pixels).
    void countPass(int64_t pass) { ++counts_[pass & 1]; }
    // The variance estimates of the render's image after the counted passes, whose pixel i
    // is radianceAt(i) (read pixel by pixel: no copy of the image, 12 bytes a pixel at a
    // frame's peak), lights seen directly told by `lights` too; nullopt for a render resumed
    // from a checkpoint that had no halves.
    template <class RadianceAt>
    std::optional<PixelErrors> errors(int width, int height, RadianceAt radianceAt, const LightsInView& lights,
                                      double decay) const {
        if (!known_) return std::nullopt;
        return pixelErrorsOf(width, height, [&](size_t i) { return luminance(radianceAt(i)); }, varianceAt(),
                             lights.light(), decay);
    }
    // Their moments alone, keeping nothing of the frame's size.
    template <class RadianceAt>
    std::optional<ErrorMoments> moments(int width, int height, RadianceAt radianceAt, const LightsInView& lights) const {
        if (!known_) return std::nullopt;
        return errorMomentsOf(width, height, [&](size_t i) { return luminance(radianceAt(i)); }, varianceAt(),
                              lights.light());
    }

    // Checkpoints carry the halves after the integrator's own state. A checkpoint written
    // before they existed has none: the render then resumes without an error estimate.
    void save(std::ostream& out) const;
    // Reads the halves if the stream holds them (and nothing else is left), else marks
    // them unknown; throws CheckpointError, changing nothing, on a damaged or partial block
    // or one whose pass counts do not add up to `passes`.
    void restore(std::istream& in, int64_t passes);

private:
    PixelFigure varianceAt() const {
        return [this](size_t i) { return halfSplitVariance(sums_[2 * i + 1], sums_[2 * i], counts_[1], counts_[0]); };
    }
    std::vector<float> sums_;  // per pixel: odd-pass sum, even-pass sum
    int64_t counts_[2] = {0, 0};
    bool known_ = true;
};

}  // namespace photon
