// render.adaptive_camera_paths: how many camera paths each pixel traces in a pass. The
// first stores the pixel's visible point as always; the others bring only the light the
// camera side finds (direct light, what the coat's and the glass's branches reach). The
// pixel's direct light is the mean over all the paths it traced, each drawn alike; the
// photons' part stays with the first path of each pass.
//
// A pass costs C = c sum_p n_p + T_photons and leaves variance
// V = sum_p (s_p^2 / n_p + rho_p^2): s_p^2 a camera path's variance at pixel p, rho_p^2 its
// photons'. At equal time the error is V C / time, least where d(V C) / dn_p = 0:
//     n_p = s_p sqrt(C / (c V)),
// the allocation that maximises Monte Carlo efficiency (variance x cost; Hammersley &
// Handscomb 1964), with the photon pass's cost shared among more camera paths where
// camera paths are what is noisy, and where photons are, none added; times kGain, as
// measured (below). s_p^2 is read over
// the pixel and its eight neighbours from the second moment of its paths' luminance
// (this class's sums) and their mean (the pixel's direct light); C, c and V come from the
// pass just rendered, as counts (rays, photons) and the image, never a clock, so that the
// choice is the same for a seed on any thread count and after a resume.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <istream>
#include <limits>
#include <ostream>
#include <vector>

namespace photon {

class AdaptiveCameraPaths {
public:
    AdaptiveCameraPaths() = default;
    AdaptiveCameraPaths(int width, int height)
        : width_(width), height_(height), pixels_(static_cast<size_t>(width) * height) {}

    // The paths pixel `pixel` is to trace in the next pass, as a real number (the caller
    // rounds it at random to a whole number of that mean); directAt(j) is the luminance of
    // pixel j's direct light summed over the paths it traced.
    template <class DirectAt>
    float pathsAt(size_t pixel, DirectAt&& directAt) const {
        if (!(scale_ > 0)) return 1.0f;
        return std::clamp(scale_ * static_cast<float>(std::sqrt(variance(pixel, directAt))), 1.0f, kMaxPaths);
    }
    // A pass's `paths` paths at `pixel` and the sum of their luminances squared.
    void add(size_t pixel, float paths, float squares) {
        Pixel& p = pixels_[pixel];
        p.paths += paths;
        // A sum past a float's range (or a NaN) is held at the largest float: only the
        // counts read it, and a checkpoint, which refuses what is not finite, must restore.
        const float sum = p.squares + squares;
        p.squares = sum <= std::numeric_limits<float>::max() ? sum : std::numeric_limits<float>::max();
    }
    // The paths pixel `pixel` has traced, over which its direct light is averaged.
    float pathsTraced(size_t pixel) const { return pixels_[pixel].paths; }

    // Sets the scale kGain sqrt(C / (c V)) from the pass just rendered: its cost and one
    // camera path's, in camera rays, and the variance of a pass's estimate summed over
    // pixels (the error estimate's, camera paths and photons together, with the counts as
    // given).
    void decide(double passCost, double pathCost, double passVariance) {
        if (pathCost > 0 && passVariance > 0)
            scale_ = kGain * static_cast<float>(std::sqrt(passCost / (pathCost * passVariance)));
    }

    void save(std::ostream& out) const;
    // Reads the block save() wrote if the stream is at one. A checkpoint written before it
    // existed traced one path a pixel a pass: each pixel has then traced `renderPasses`,
    // whose variance is not known (taken as none, so counts grow as passes teach them);
    // directAt as for pathsAt. Throws CheckpointError on a damaged block.
    template <class DirectAt>
    void restore(std::istream& in, int64_t renderPasses, DirectAt&& directAt) {
        if (restoreBlock(in, renderPasses)) return;
        scale_ = 0;
        const float paths = static_cast<float>(renderPasses);
        for (size_t i = 0; i < pixels_.size(); ++i) {
            const float mean = paths > 0 ? static_cast<float>(directAt(i)) / paths : 0.0f;
            pixels_[i] = {paths, paths * mean * mean};
        }
    }

    // The model counts rays alone (not the photons' gather and grid) and passes as
    // independent (the photons' progressive estimate is not): at equal time, luminance noise
    // with the model's scale times 1 / 1.6 / 2.5 was 0.125 / 0.116 / 0.111 on
    // scenes/textured-mesh.json, 0.121 / 0.108 / 0.108 on translucent-sheet, 0.064 / 0.060
    // on envmap, 0.0110 / 0.0104 / 0.0106 on the Bitterli Cornell box (its RGB noise 0.0157
    // / 0.0152 / 0.0190), 0.173 / 0.171 / 0.179 on coffee, 0.075 / 0.075 on cornell-glass.
    static constexpr float kGain = 1.6f;
    static constexpr float kMaxPaths = 16;
    static constexpr size_t kBytesPerPixel = 8;

private:
    // false, the stream where it was, if it is not at a block of this class.
    bool restoreBlock(std::istream& in, int64_t renderPasses);

    // A camera path's variance at `pixel`: the mean over it and its neighbours of each
    // one's second moment less its mean squared.
    template <class DirectAt>
    double variance(size_t pixel, DirectAt& directAt) const {
        const int x = static_cast<int>(pixel % static_cast<size_t>(width_)), y = static_cast<int>(pixel / width_);
        double sum = 0;
        int count = 0;
        for (int yy = std::max(y - 1, 0); yy <= std::min(y + 1, height_ - 1); ++yy)
            for (int xx = std::max(x - 1, 0); xx <= std::min(x + 1, width_ - 1); ++xx) {
                const size_t j = static_cast<size_t>(yy) * width_ + xx;
                const Pixel& p = pixels_[j];
                if (!(p.paths > 0)) continue;
                const double paths = static_cast<double>(p.paths), mean = static_cast<double>(directAt(j)) / paths;
                sum += std::max(static_cast<double>(p.squares) / paths - mean * mean, 0.0);
                ++count;
            }
        return count > 0 ? sum / count : 0.0;
    }

    struct Pixel {
        float paths = 0;    // camera paths traced (whole numbers, exact in a float to 2^24)
        float squares = 0;  // the sum of their luminances squared
    };
    static_assert(sizeof(Pixel) == kBytesPerPixel);
    int width_ = 0, height_ = 0;
    float scale_ = 0;  // sqrt(C / (c V)); 0 until the first decision
    std::vector<Pixel> pixels_;
};

}  // namespace photon
