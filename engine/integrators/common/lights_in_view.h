// The lights each pixel shows straight from the camera, by their emitted luminance: what
// the error estimate (film/pixel_errors.h) tells lights seen directly by, with the pixel's
// own luminance. A pixel that a light's edge crosses sees the light in some passes and not
// in others, so its variance dwarfs any other's; told apart by the pixel's luminance alone
// (25 times the image's mean) such a pixel drops in and out of the estimate as the mean
// moves, and on a 16 x 16 image of the Bitterli Cornell box the estimate swung between 14%
// and 352% from one pass to the next (docs/error-estimate.md). The light's own luminance
// does not depend on how much of the pixel it covers.
#pragma once
#include <algorithm>
#include <cstdint>
#include <mutex>
#include <vector>
#include "film/pixel_errors.h"
#include "scene/scene.h"

namespace photon {

class LightsInView {
public:
    explicit LightsInView(const Scene& scene)
        : scene_(&scene), width_(scene.camera().width()), height_(scene.camera().height()) {}

    // The luminance of the brightest emitting surface that pixel (x, y) shows, 0 if none:
    // of the surfaces that the rays through its centre and its corners, from the lens's
    // centre, land on first (past boundaries between media), where they emit toward the
    // camera. Found by about two rays a pixel when first asked (the lattice of corners is
    // shared; 0.62 s for a 3840 x 2160 Cornell box on two threads, 2.4 times one ray a
    // pixel), then kept as a byte (within 5%: kStepsPerOctave) for each pixel that shows a
    // light and nothing for the others; the same on any thread count. None in a scene where
    // no shape emits.
    // The first call runs a parallel loop of its own: call it first outside any parallel
    // loop that would then call it.
    float at(int x, int y) const {
        std::call_once(found_, [this] { find(); });
        if (rowStart_.empty()) return 0.0f;
        // The row's lit pixels, by x: (x << 8) | code, ascending.
        const auto first = lit_.begin() + rowStart_[y], last = lit_.begin() + rowStart_[y + 1];
        const auto found = std::lower_bound(first, last, static_cast<uint32_t>(x) << 8);
        return found != last && (*found >> 8) == static_cast<uint32_t>(x) ? decode(static_cast<uint8_t>(*found & 0xff)) : 0.0f;
    }
    // at() as the error estimate reads it.
    PixelLight light() const {
        return [this](int x, int y) { return at(x, y); };
    }

    // Luminances as 1 + round(7 (log2 L + 16)): 2^-16 to 2^20.4 in steps of 1/7 octave
    // (10%, so within 5%); 0 for none.
    static constexpr float kStepsPerOctave = 7, kLeastOctave = -16;
    static uint8_t encode(float luminance);
    static float decode(uint8_t code);
    // What the lights take in memory once found: 4 bytes a row and 4 a pixel that shows one
    // (a light filling 0.3% of a 3840 x 2160 frame, as scenes/cornell-box.json's: 0.013
    // bytes a pixel, where a byte for every pixel took 8 MB).
    size_t bytes() const {
        std::call_once(found_, [this] { find(); });
        return (rowStart_.size() + lit_.size()) * sizeof(uint32_t);
    }

private:
    void find() const;

    const Scene* scene_;
    int width_, height_;
    mutable std::once_flag found_;
    // Row y's lit pixels are lit_[rowStart_[y], rowStart_[y + 1]).
    mutable std::vector<uint32_t> rowStart_, lit_;
};

}  // namespace photon
