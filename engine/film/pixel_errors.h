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
#include <vector>
#include <photon/image.h>

namespace photon {

struct PixelErrors {
    int width = 0, height = 0;
    std::vector<float> luminance;  // the image's, per pixel
    std::vector<float> variance;   // the estimated variance of that luminance
    // The error falls as passes^-decay: 1/2 for independent samples of one distribution;
    // alpha / 2 for SPPM, whose passes' variance grows as their radius shrinks (Knaus &
    // Zwicker 2011, sec. 4.2: Var_i ~ i^(1 - alpha), so the mean's is ~ N^-alpha).
    double decay = 0.5;
};

// Var F from the halves' luminance sums (see above); 0 until each half has a pass.
inline float halfSplitVariance(double oddSum, double evenSum, int64_t oddCount, int64_t evenCount) {
    if (oddCount <= 0 || evenCount <= 0) return 0;
    const double d = oddSum / double(oddCount) - evenSum / double(evenCount);
    const double n = double(oddCount + evenCount);
    return float(d * d * double(oddCount) * double(evenCount) / (n * n));
}

// The pixels the relative error is measured over: all but lights seen directly, i.e.
// pixels brighter than 25 times the image's mean luminance (the rule the comparisons with
// reference images follow), and their eight neighbours: the pixels a light's edge crosses,
// which see it in some passes and not others, have little to do with light transport but
// a variance far above any other's, and would make the estimate hinge on a few pixels.
std::vector<bool> errorPixels(const std::vector<float>& luminance, int width, int height);

// Means over errorPixels of the variance estimates and of the luminance (0 with none).
struct ErrorMoments {
    double variance = 0, luminance = 0;
};
ErrorMoments errorMoments(const PixelErrors& e);

// The image's relative error: RMS over errorPixels of the estimated standard error, over
// their mean luminance (the relative noise photon-bench measures from two seeds). Summed
// in a fixed order, so the same passes give the same figure on any thread count.
double relativeErrorOf(const PixelErrors& e);

// The heat map: a layer "error" with channels sd (the standard error of luminance, in the
// image's units), relative (sd / luminance) and luminance, each a 5 x 5 box mean of the
// per-pixel estimates (25 degrees of freedom instead of one: about 14% precision).
ImageLayer errorLayer(const PixelErrors& e);

}  // namespace photon
