// A linear RGB image: what integrators hand out as snapshots.
#pragma once
#include <cmath>
#include <vector>
#include "../math/vec.h"

namespace photon {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // row-major, top row first, 3 floats per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}
    Color at(int x, int y) const {
        size_t i = (static_cast<size_t>(y) * width + x) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    void set(int x, int y, Color c) {
        size_t i = (static_cast<size_t>(y) * width + x) * 3;
        rgb[i] = c.x;
        rgb[i + 1] = c.y;
        rgb[i + 2] = c.z;
    }
};

// Root-mean-square difference over all pixels and channels of two images of one size.
inline double rmse(const Image& a, const Image& b) {
    double sum = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        double d = static_cast<double>(a.rgb[i]) - static_cast<double>(b.rgb[i]);
        sum += d * d;
    }
    return a.rgb.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

}  // namespace photon
