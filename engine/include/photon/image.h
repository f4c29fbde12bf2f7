// Linear RGB images: what a render hands out as snapshots, and an image with extra named
// layers of three channels each for formats that hold them (multi-channel EXR): the main
// image's channels are R, G, B; a layer's are "<name>.<channel>", e.g. raw.R, normal.X.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <vector>
#include <photon/vec.h>

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

struct ImageLayer {
    std::string name;
    std::array<std::string, 3> channels;  // e.g. {"R", "G", "B"} or {"X", "Y", "Z"}
    Image image;                          // the main image's size
};

struct LayeredImage {
    Image main;
    std::vector<ImageLayer> layers;
};

}  // namespace photon
