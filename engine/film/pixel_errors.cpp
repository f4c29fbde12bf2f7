#include "film/pixel_errors.h"
#include <cmath>

namespace photon {
namespace {

constexpr int kBoxRadius = 2;  // 5 x 5 pixels

// Box mean of `values` (w x h) over (2r+1)^2 pixels, clipped at the borders: summed-area
// rows then columns, O(1) a pixel.
std::vector<float> boxMean(const std::vector<float>& values, int w, int h, int r) {
    std::vector<double> rows(values.size());
    for (int y = 0; y < h; ++y) {
        const float* in = &values[size_t(y) * w];
        double* out = &rows[size_t(y) * w];
        double sum = 0;
        int lo = 0, hi = -1;
        for (int x = 0; x < w; ++x) {
            while (hi < std::min(w - 1, x + r)) sum += in[++hi];
            while (lo < x - r) sum -= in[lo++];
            out[x] = sum / double(hi - lo + 1);
        }
    }
    std::vector<float> result(values.size());
    for (int x = 0; x < w; ++x) {
        double sum = 0;
        int lo = 0, hi = -1;
        for (int y = 0; y < h; ++y) {
            while (hi < std::min(h - 1, y + r)) sum += rows[size_t(++hi) * w + x];
            while (lo < y - r) sum -= rows[size_t(lo++) * w + x];
            result[size_t(y) * w + x] = float(sum / double(hi - lo + 1));
        }
    }
    return result;
}

}  // namespace

std::vector<bool> errorPixels(const std::vector<float>& luminance, int width, int height) {
    std::vector<bool> keep(luminance.size(), true);
    if (luminance.empty()) return keep;
    double mean = 0;
    for (float y : luminance) mean += y;
    mean /= double(luminance.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (luminance[size_t(y) * width + x] <= 25 * mean) continue;
            for (int j = std::max(0, y - 1); j <= std::min(height - 1, y + 1); ++j)
                for (int i = std::max(0, x - 1); i <= std::min(width - 1, x + 1); ++i) keep[size_t(j) * width + i] = false;
        }
    return keep;
}

ErrorMoments errorMoments(const PixelErrors& e) {
    const std::vector<bool> keep = errorPixels(e.luminance, e.width, e.height);
    double sum = 0, variance = 0;
    size_t kept = 0;
    for (size_t i = 0; i < keep.size(); ++i)
        if (keep[i]) sum += e.luminance[i], variance += e.variance[i], ++kept;
    if (kept == 0) return {};
    return {variance / double(kept), sum / double(kept)};
}

double relativeErrorOf(const PixelErrors& e) {
    const ErrorMoments m = errorMoments(e);
    if (m.luminance <= 0) return 0;
    return std::sqrt(m.variance) / m.luminance;
}

ImageLayer errorLayer(const PixelErrors& e) {
    ImageLayer layer{"error", {"sd", "relative", "luminance"}, Image(e.width, e.height)};
    const std::vector<float> variance = boxMean(e.variance, e.width, e.height, kBoxRadius);
    const std::vector<float> luminance = boxMean(e.luminance, e.width, e.height, kBoxRadius);
    for (size_t i = 0; i < variance.size(); ++i) {
        const float sd = std::sqrt(std::max(variance[i], 0.0f));
        float* px = &layer.image.rgb[3 * i];
        px[0] = sd;
        px[1] = luminance[i] > 0 ? sd / luminance[i] : 0.0f;
        px[2] = e.luminance[i];
    }
    return layer;
}

}  // namespace photon
