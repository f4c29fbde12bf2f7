// Which pixels show a light's emitting surface straight from the camera: the pixels the
// error estimate leaves out (film/pixel_errors.h) with their neighbours, whatever their
// luminance. A pixel that a light's edge crosses sees the light in some passes and not in
// others, so its variance dwarfs any other's; told apart by luminance alone (25 times the
// image's mean) such a pixel drops in and out of the estimate as the mean moves, and on a
// 16 x 16 image of the Bitterli Cornell box the estimate swung between 14% and 352% from
// one pass to the next (docs/error-estimate.md).
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

    // Whether pixel (x, y) shows an emitting surface: a ray through its centre or one of
    // its corners, from the lens's centre, lands first on a surface that emits toward the
    // camera (past boundaries between media). Found by about two rays a pixel when first
    // asked (the lattice of corners is shared; 0.62 s for a 3840 x 2160 Cornell box on two
    // threads, 2.4 times one ray a pixel), then kept in a bit a pixel; the same on any thread
    // count. None in a scene where no shape emits.
    bool at(int x, int y) const {
        trace();
        if (rows_.empty()) return false;
        return (rows_[static_cast<size_t>(y) * wordsPerRow_ + static_cast<size_t>(x >> 6)] >> (x & 63)) & 1;
    }

    // Finds the pixels if not yet done. at() does so when first called; call it first where
    // at() is then called from a parallel loop (the search runs one of its own).
    void trace() const {
        std::call_once(found_, [this] { find(); });
    }

    // at() as the error estimate reads it.
    PixelFlag flag() const {
        return [this](int x, int y) { return at(x, y); };
    }

private:
    void find() const;

    const Scene* scene_;
    int width_, height_;
    mutable std::once_flag found_;
    // Each row's bits in words of its own, so that rows are found in parallel.
    mutable std::vector<uint64_t> rows_;
    mutable size_t wordsPerRow_ = 0;
};

}  // namespace photon
