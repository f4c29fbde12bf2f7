#include "film/pixel_errors.h"
#include <algorithm>
#include <cmath>

namespace photon {
namespace {

constexpr int kBoxRadius = 2;  // 5 x 5 pixels

// Box mean over (2r+1)^2 pixels of a w x h frame, clipped at the borders, streamed a row at
// a time: the sums of each column over the rows in reach, then a window sliding along them.
// O(1) a pixel in a row of doubles, where summed-area rows of the whole frame took 8 bytes
// a pixel, and at a 3840 x 2160 frame's end, with the image and its layer, made its peak.
template <class At, class Out>
void boxMean(int w, int h, int r, At at, Out out) {
    std::vector<double> column(size_t(w), 0.0);
    int top = 0, bottom = -1;  // the rows summed in column
    for (int y = 0; y < h; ++y) {
        for (; bottom < std::min(h - 1, y + r); ++bottom)
            for (int x = 0; x < w; ++x) column[x] += at(size_t(bottom + 1) * w + x);
        for (; top < y - r; ++top)
            for (int x = 0; x < w; ++x) column[x] -= at(size_t(top) * w + x);
        const double rows = bottom - top + 1;
        double sum = 0;
        int left = 0, right = -1;
        for (int x = 0; x < w; ++x) {
            while (right < std::min(w - 1, x + r)) sum += column[++right];
            while (left < x - r) sum -= column[left++];
            out(size_t(y) * w + x, float(sum / (rows * double(right - left + 1))));
        }
    }
}

}  // namespace

void forErrorPixels(int width, int height, const PixelFigure& luminanceAt, const PixelLight& lightAt,
                    const std::function<void(size_t pixel, float luminance, bool kept)>& visit) {
    const size_t n = size_t(width) * height;
    if (n == 0) return;
    double mean = 0;
    for (size_t i = 0; i < n; ++i) mean += luminanceAt(i);
    mean /= double(n);
    // Rows y - 1, y and y + 1 of the luminance, in a ring of three, and of what is tested:
    // the brighter of the pixel and the light it shows.
    std::vector<float> rows(size_t(3) * width), shown(size_t(3) * width);
    auto row = [&](int y) { return &rows[size_t(y % 3) * width]; };
    auto tested = [&](int y) { return &shown[size_t(y % 3) * width]; };
    auto load = [&](int y) {
        float *r = row(y), *t = tested(y);
        for (int x = 0; x < width; ++x) {
            r[x] = luminanceAt(size_t(y) * width + x);
            t[x] = lightAt ? std::max(r[x], lightAt(x, y)) : r[x];
        }
    };
    load(0);
    for (int y = 0; y < height; ++y) {
        if (y + 1 < height) load(y + 1);
        for (int x = 0; x < width; ++x) {
            bool kept = true;
            for (int j = std::max(0, y - 1); j <= std::min(height - 1, y + 1) && kept; ++j)
                for (int i = std::max(0, x - 1); i <= std::min(width - 1, x + 1); ++i)
                    if (tested(j)[i] > 25 * mean) kept = false;
            visit(size_t(y) * width + x, row(y)[x], kept);
        }
    }
}

std::vector<bool> errorPixels(const std::vector<float>& luminance, int width, int height) {
    std::vector<bool> keep(luminance.size(), true);
    forErrorPixels(width, height, [&](size_t i) { return luminance[i]; }, {},
                   [&](size_t i, float, bool kept) { keep[i] = kept; });
    return keep;
}

namespace {
// The moments, storing each pixel's variance in `variance` when it is given.
ErrorMoments measure(int width, int height, const PixelFigure& luminanceAt, const PixelFigure& varianceAt,
                     const PixelLight& lightAt, std::vector<uint16_t>* variance) {
    double sum = 0, varianceSum = 0;
    size_t kept = 0;
    forErrorPixels(width, height, luminanceAt, lightAt, [&](size_t i, float luminance, bool keep) {
        const float v = varianceAt(i);
        if (variance) (*variance)[i] = toBfloat16(v);
        if (keep) sum += luminance, varianceSum += v, ++kept;
    });
    if (kept == 0) return {};
    return {varianceSum / double(kept), sum / double(kept)};
}
}  // namespace

ErrorMoments errorMomentsOf(int width, int height, const PixelFigure& luminanceAt, const PixelFigure& varianceAt,
                            const PixelLight& lightAt) {
    return measure(width, height, luminanceAt, varianceAt, lightAt, nullptr);
}

PixelErrors pixelErrorsOf(int width, int height, const PixelFigure& luminanceAt, const PixelFigure& varianceAt,
                          const PixelLight& lightAt, double decay) {
    PixelErrors e;
    e.width = width, e.height = height, e.decay = decay;
    e.variance.resize(size_t(width) * height);
    e.moments = measure(width, height, luminanceAt, varianceAt, lightAt, &e.variance);
    return e;
}

double relativeErrorOf(const PixelErrors& e) {
    if (e.moments.luminance <= 0) return 0;
    return std::sqrt(e.moments.variance) / e.moments.luminance;
}

ImageLayer errorLayer(const PixelErrors& e, const Image& image) {
    ImageLayer layer{"error", {"sd", "relative", "luminance"}, Image(e.width, e.height)};
    float* px = layer.image.rgb.data();
    auto luminanceAt = [&](size_t i) {
        return luminance(Color(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]));
    };
    boxMean(e.width, e.height, kBoxRadius, [&](size_t i) { return e.varianceAt(i); },
            [&](size_t i, float variance) { px[3 * i] = std::sqrt(std::max(variance, 0.0f)); });
    boxMean(e.width, e.height, kBoxRadius, luminanceAt, [&](size_t i, float meanLuminance) {
        px[3 * i + 1] = meanLuminance > 0 ? px[3 * i] / meanLuminance : 0.0f;
        px[3 * i + 2] = luminanceAt(i);
    });
    return layer;
}

}  // namespace photon
