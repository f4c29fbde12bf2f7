#include "post/bilateral.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace photon {

namespace {

// 1 / (2 sigma^2): the Gaussian's exponent per squared distance; 0 for an infinite sigma,
// and finite for the tiniest one (so that a zero distance still gives exponent 0).
float gaussianFactor(float sigma) {
    if (std::isinf(sigma)) return 0.0f;
    return std::min(1.0f / (2.0f * sigma * sigma), 1e30f);
}

// e^-x for x >= 0, as 2^-x/ln2 split into 2^i (the exponent bits) and 2^f for
// f in [-1/2, 1/2] (its Taylor series to degree 6, relative error < 2e-7). Unlike
// std::exp it has no library call, so the compiler can vectorise the filter's inner
// loop: it runs once per pixel and tap, ~30 million times for a 512x512 image.
// e^0 is exactly 1, and anything below e^-87 is 0.
inline float expNegative(float x) {
    float t = std::min(x, 87.0f) * -1.44269504f;
    float i = std::floor(t + 0.5f);
    float f = t - i;
    float p = 1.0f + f * (0.693147181f + f * (0.240226507f + f * (0.0555041087f +
              f * (0.00961812911f + f * (0.00133335581f + f * 0.000154035304f)))));
    float scale = std::bit_cast<float>(static_cast<int32_t>(i + 127.0f) << 23);
    return x < 87.0f ? p * scale : 0.0f;
}

// ln(I + eps) per channel (see BilateralParams::sigmaRange for why).
std::vector<float> logColours(const Image& image) {
    double sum = 0;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    for (size_t p = 0; p < pixels; ++p)
        sum += luminance({image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]});
    const float eps = std::max(0.01f * static_cast<float>(sum / std::max<size_t>(pixels, 1)), 1e-8f);
    std::vector<float> out(image.rgb.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = std::log(std::max(image.rgb[i], 0.0f) + eps);
    return out;
}

// Every range term's channels side by side, K floats per pixel, each scaled by the square
// root of its Gaussian factor: a tap's exponent is then the spatial one plus the plain
// squared distance of two K-vectors.
struct Features {
    int k = 0;
    std::vector<float> values;
};

Features rangeFeatures(const Image& image, const BilateralParams& params, const BilateralGuides& guides) {
    const std::vector<float> logs = logColours(image);
    // Colour terms are root-mean-square over their 3 channels: the factor divided by 3.
    std::vector<std::pair<const float*, float>> terms{{logs.data(), gaussianFactor(params.sigmaRange) / 3.0f}};
    if (guides.albedo) terms.push_back({guides.albedo->rgb.data(), gaussianFactor(params.sigmaAlbedo) / 3.0f});
    if (guides.normal) terms.push_back({guides.normal->rgb.data(), gaussianFactor(params.sigmaNormal)});
    Features f{3 * static_cast<int>(terms.size()), {}};
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    f.values.resize(pixels * f.k);
    for (size_t t = 0; t < terms.size(); ++t) {
        const float scale = std::sqrt(terms[t].second);
        for (size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < 3; ++c) f.values[p * f.k + 3 * t + c] = scale * terms[t].first[3 * p + c];
    }
    return f;
}

// The filter with K feature floats per pixel known at compile time, for the inner loop.
template <int K>
void filterRows(const Image& image, const Features& f, const std::vector<float>& spatial, int radius, Image& out) {
    const int w = image.width, h = image.height, side = 2 * radius + 1;
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x < w; ++x) {
                const size_t p = static_cast<size_t>(y) * w + x;
                const float* fp = &f.values[p * K];
                float r = 0, g = 0, b = 0, weights = 0;
                const int x0 = std::max(0, x - radius), x1 = std::min(w - 1, x + radius);
                for (int qy = std::max(0, y - radius); qy <= std::min(h - 1, y + radius); ++qy) {
                    // The spatial weights' row for qy, read at column qx - x + radius (a pointer
                    // offset to column x - radius would point before the vector: undefined).
                    const float* sp = &spatial[(qy - y + radius) * side] + radius - x + x0;
                    const size_t row = static_cast<size_t>(qy) * w;
                    for (int qx = x0; qx <= x1; ++qx) {
                        const float* fq = &f.values[(row + qx) * K];
                        float exponent = sp[qx - x0];
                        for (int k = 0; k < K; ++k) exponent += (fq[k] - fp[k]) * (fq[k] - fp[k]);
                        // One exponential per tap for the product of all the Gaussians.
                        const float weight = expNegative(exponent);
                        const float* c = &image.rgb[3 * (row + qx)];
                        weights += weight;
                        r += weight * c[0];
                        g += weight * c[1];
                        b += weight * c[2];
                    }
                }
                // The centre's weight is exactly 1, so weights >= 1.
                out.rgb[3 * p] = r / weights;
                out.rgb[3 * p + 1] = g / weights;
                out.rgb[3 * p + 2] = b / weights;
            }
    });
}

}  // namespace

int bilateralRadius(float sigmaSpatial) { return static_cast<int>(std::ceil(3.0f * sigmaSpatial)); }

Image bilateralFilter(const Image& image, const BilateralParams& params, const BilateralGuides& guides) {
    for (const Image* g : {guides.albedo, guides.normal})
        if (g && (g->width != image.width || g->height != image.height))
            throw std::invalid_argument("bilateral filter: a guide's size differs from the image's");
    const int radius = bilateralRadius(params.sigmaSpatial), side = 2 * radius + 1;
    std::vector<float> spatial(static_cast<size_t>(side) * side);
    const float spatialFactor = gaussianFactor(params.sigmaSpatial);
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
            spatial[(dy + radius) * side + dx + radius] = spatialFactor * static_cast<float>(dx * dx + dy * dy);

    const Features f = rangeFeatures(image, params, guides);
    Image out(image.width, image.height);
    switch (f.k) {
        case 3: filterRows<3>(image, f, spatial, radius, out); break;
        case 6: filterRows<6>(image, f, spatial, radius, out); break;
        default: filterRows<9>(image, f, spatial, radius, out); break;
    }
    return out;
}

}  // namespace photon
