#include "bilateral.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace photon {

namespace {

// 1 / (2 sigma^2): the Gaussian's exponent per squared distance; 0 for an infinite sigma,
// and finite for the tiniest one (so that a zero distance still gives exponent 0).
float gaussianFactor(float sigma) {
    if (std::isinf(sigma)) return 0.0f;
    return std::min(1.0f / (2.0f * sigma * sigma), 1e30f);
}

float squaredDistance(const float* a, const float* b) {
    float dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
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

// The exponents of every term but the spatial one, per channel triple: a guide image and
// the factor its squared distance is multiplied by.
struct RangeTerm {
    const float* values;
    float factor;
};

}  // namespace

int bilateralRadius(float sigmaSpatial) { return static_cast<int>(std::ceil(3.0f * sigmaSpatial)); }

Image bilateralFilter(const Image& image, const BilateralParams& params, const BilateralGuides& guides) {
    for (const Image* g : {guides.albedo, guides.normal})
        if (g && (g->width != image.width || g->height != image.height))
            throw std::invalid_argument("bilateral filter: a guide's size differs from the image's");
    const int w = image.width, h = image.height, radius = bilateralRadius(params.sigmaSpatial);
    const std::vector<float> logs = logColours(image);
    // Root-mean-square over 3 channels: the squared distance divided by 3.
    std::vector<RangeTerm> terms{{logs.data(), gaussianFactor(params.sigmaRange) / 3.0f}};
    if (guides.albedo) terms.push_back({guides.albedo->rgb.data(), gaussianFactor(params.sigmaAlbedo) / 3.0f});
    if (guides.normal) terms.push_back({guides.normal->rgb.data(), gaussianFactor(params.sigmaNormal)});

    const int side = 2 * radius + 1;
    std::vector<float> spatial(static_cast<size_t>(side) * side);
    const float spatialFactor = gaussianFactor(params.sigmaSpatial);
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
            spatial[(dy + radius) * side + dx + radius] = spatialFactor * static_cast<float>(dx * dx + dy * dy);

    Image out(w, h);
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x < w; ++x) {
                const size_t p = 3 * (static_cast<size_t>(y) * w + x);
                float sum[3] = {0, 0, 0}, weights = 0;
                for (int qy = std::max(0, y - radius); qy <= std::min(h - 1, y + radius); ++qy)
                    for (int qx = std::max(0, x - radius); qx <= std::min(w - 1, x + radius); ++qx) {
                        const size_t q = 3 * (static_cast<size_t>(qy) * w + qx);
                        float exponent = spatial[(qy - y + radius) * side + qx - x + radius];
                        for (const RangeTerm& t : terms) exponent += t.factor * squaredDistance(t.values + p, t.values + q);
                        // One exp per tap for all the Gaussians' product.
                        float weight = std::exp(-exponent);
                        weights += weight;
                        for (int c = 0; c < 3; ++c) sum[c] += weight * image.rgb[q + c];
                    }
                // The centre's weight is 1, so weights >= 1.
                for (int c = 0; c < 3; ++c) out.rgb[p + c] = sum[c] / weights;
            }
    });
    return out;
}

}  // namespace photon
