#include "import/pbrt/scattering_presets.h"
#include <array>
#include <cmath>

namespace photon::pbrt {

namespace {

struct Preset {
    std::string_view name;
    ScatteringCoefficients mm;
};

// Jensen et al. 2001, table 2 (sigma_s' and sigma_a in mm^-1).
const std::array<Preset, 12> kPresets{{
    {"Apple", {{0.0030f, 0.0034f, 0.046f}, {2.29f, 2.39f, 1.97f}}},
    {"Chicken1", {{0.015f, 0.077f, 0.19f}, {0.15f, 0.21f, 0.38f}}},
    {"Chicken2", {{0.018f, 0.088f, 0.20f}, {0.19f, 0.25f, 0.32f}}},
    {"Cream", {{0.0002f, 0.0028f, 0.0163f}, {7.38f, 5.47f, 3.15f}}},
    {"Ketchup", {{0.061f, 0.97f, 1.45f}, {0.18f, 0.07f, 0.03f}}},
    {"Marble", {{0.0021f, 0.0041f, 0.0071f}, {2.19f, 2.62f, 3.00f}}},
    {"Potato", {{0.0024f, 0.0090f, 0.12f}, {0.68f, 0.70f, 0.55f}}},
    {"Skimmilk", {{0.0014f, 0.0025f, 0.0142f}, {0.70f, 1.22f, 1.90f}}},
    {"Skin1", {{0.032f, 0.17f, 0.48f}, {0.74f, 0.88f, 1.01f}}},
    {"Skin2", {{0.013f, 0.070f, 0.145f}, {1.09f, 1.59f, 1.79f}}},
    {"Spectralon", {{0.0f, 0.0f, 0.0f}, {11.6f, 20.4f, 14.9f}}},
    {"Wholemilk", {{0.0011f, 0.0024f, 0.014f}, {2.55f, 3.21f, 3.77f}}},
}};

}  // namespace

std::optional<ScatteringCoefficients> scatteringPreset(std::string_view name) {
    for (const Preset& p : kPresets)
        if (p.name == name) return p.mm;
    return std::nullopt;
}

std::string scatteringPresetNames() {
    std::string names;
    for (const Preset& p : kPresets) names += (names.empty() ? "" : ", ") + std::string(p.name);
    return names;
}

}  // namespace photon::pbrt
