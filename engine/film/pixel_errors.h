// How far a render's image may be from its converged value: per-pixel variance estimates
// from two half-images (the passes with an odd index and those with an even one), the
// image's relative error that render.target_error stops at, and the heat-map layer.
//
// Passes that are independent estimates split into two independent halves; with A and B
// their means over n_odd and n_even passes, the whole render's mean F has
// Var F = Var(A - B) n_odd n_even / N^2 (for n_odd = n_even: Var F = Var(S_odd - S_even) / N^2
// for the halves' sums, whatever each pass's own variance, so SPPM's shrinking radius is
// allowed for). One pixel's (A - B)^2 is an unbiased estimate of Var(A - B) with one degree
// of freedom: noisy alone, accurate summed over an image or smoothed for the heat map.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>
#include <photon/image.h>
#include "math/bfloat16.h"

namespace photon {

// Means over errorPixels of the variance estimates and of the luminance (0 with none).
struct ErrorMoments {
    double variance = 0, luminance = 0;
};

struct PixelErrors {
    int width = 0, height = 0;
    // Each pixel's estimated variance of its luminance, in bfloat16 (0.4%; the heat map
    // averages 25 of them, each with one degree of freedom, to about 14%): 2 bytes a pixel.
    // A render holds them from pass to pass for its images' heat maps; the luminance and
    // variance in floats took 8, which put a 3840 x 2160 frame's peak 2.6% over 1 GiB.
    std::vector<uint16_t> variance;
    ErrorMoments moments;  // over errorPixels, in full precision
    // The error falls as passes^-decay: 1/2 for independent samples of one distribution;
    // alpha / 2 for SPPM, whose passes' variance grows as their radius shrinks (Knaus &
    // Zwicker 2011, sec. 4.2: Var_i ~ i^(1 - alpha), so the mean's is ~ N^-alpha).
    double decay = 0.5;
    float varianceAt(size_t i) const { return fromBfloat16(variance[i]); }
};

// Var F from the halves' luminance sums (see above); 0 until each half has a pass.
inline float halfSplitVariance(double oddSum, double evenSum, int64_t oddCount, int64_t evenCount) {
    if (oddCount <= 0 || evenCount <= 0) return 0;
    const double d = oddSum / double(oddCount) - evenSum / double(evenCount);
    const double n = double(oddCount + evenCount);
    return float(d * d * double(oddCount) * double(evenCount) / (n * n));
}

// A pixel's figure, read where it is kept (no copy of the frame).
using PixelFigure = std::function<float(size_t pixel)>;
// The luminance of the brightest light pixel (x, y) shows, 0 if none
// (integrators/common/lights_in_view.h); an empty function: none known.
using PixelLight = std::function<float(int x, int y)>;

// The pixels the relative error is measured over: all but lights seen directly, i.e.
// pixels brighter than 25 times the image's mean luminance (the rule the comparisons with
// reference images follow, which also finds lights seen in mirrors and a sun in the sky)
// or that show, by `lightAt`, a light that is (however little of the pixel it covers), and
// their eight neighbours: the pixels a light's edge crosses, which see it in some passes
// and not others, have little to do with light transport but a variance far above any
// other's, and would make the estimate hinge on a few pixels. Calls visit(pixel, its
// luminance, whether it is one of them) for every pixel in order, reading each pixel's
// luminance twice (the mean, then three rows at a time) and its light once.
void forErrorPixels(int width, int height, const PixelFigure& luminanceAt, const PixelLight& lightAt,
                    const std::function<void(size_t pixel, float luminance, bool kept)>& visit);
std::vector<bool> errorPixels(const std::vector<float>& luminance, int width, int height);

// The moments of a frame whose pixels' luminance and variance estimate are read in place.
ErrorMoments errorMomentsOf(int width, int height, const PixelFigure& luminanceAt, const PixelFigure& varianceAt,
                            const PixelLight& lightAt);
// The same, keeping each pixel's variance for the heat map.
PixelErrors pixelErrorsOf(int width, int height, const PixelFigure& luminanceAt, const PixelFigure& varianceAt,
                          const PixelLight& lightAt, double decay);

// The image's relative error: RMS over errorPixels of the estimated standard error, over
// their mean luminance (the relative noise photon-bench measures from two seeds). Summed
// in a fixed order, so the same passes give the same figure on any thread count.
double relativeErrorOf(const PixelErrors& e);

// The heat map of `image`, whose errors `e` are: a layer "error" with channels sd (the
// standard error of luminance, in the image's units), relative (sd / luminance) and
// luminance (the image's own), the first two from 5 x 5 box means of the per-pixel
// estimates and luminance (25 degrees of freedom instead of one: about 14% precision).
ImageLayer errorLayer(const PixelErrors& e, const Image& image);

}  // namespace photon
