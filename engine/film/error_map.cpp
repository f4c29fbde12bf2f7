#include <photon/error_map.h>
#include <algorithm>
#include <cmath>

namespace photon {
namespace {

// sRGB 8-bit stops of the ramp at 0, 1/3, 2/3 and 1 (of log10 error from -3 to 0), close to
// matplotlib's "inferno": dark to bright and legible to the colour-blind.
constexpr float kStops[4][3] = {{0, 0, 4}, {120, 28, 109}, {237, 105, 37}, {252, 255, 164}};

float srgbToLinear(float code) {
    const float v = code / 255.0f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);  // IEC 61966-2-1
}

}  // namespace

Color errorHeatMapColor(float relativeError) {
    if (!(relativeError > 0)) return Color(srgbToLinear(kStops[0][0]), srgbToLinear(kStops[0][1]), srgbToLinear(kStops[0][2]));
    const float t = std::clamp((std::log10(relativeError) + 3.0f) / 3.0f, 0.0f, 1.0f) * 3.0f;
    const int i = std::min(2, static_cast<int>(t));
    const float f = t - static_cast<float>(i);
    float rgb[3];
    for (int c = 0; c < 3; ++c) rgb[c] = srgbToLinear(kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c]));
    return Color(rgb[0], rgb[1], rgb[2]);
}

std::optional<Image> errorHeatMap(const LayeredImage& image) {
    auto layer = std::find_if(image.layers.begin(), image.layers.end(), [](const ImageLayer& l) { return l.name == "error"; });
    if (layer == image.layers.end()) return std::nullopt;
    const Image& e = layer->image;
    Image map(e.width, e.height);
    for (int y = 0; y < e.height; ++y)
        for (int x = 0; x < e.width; ++x) {
            const Color c = e.at(x, y);  // sd, relative, luminance
            map.set(x, y, c.z > 0 ? errorHeatMapColor(c.y) : Color(0.0f));
        }
    return map;
}

}  // namespace photon
