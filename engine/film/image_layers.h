// An image with extra named layers of three channels each, for formats that hold them
// (multi-channel EXR): the main image's channels are R, G, B; a layer's are
// "<name>.<channel>", e.g. raw.R, normal.X.
#pragma once
#include <array>
#include <string>
#include <vector>
#include "image.h"

namespace photon {

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
