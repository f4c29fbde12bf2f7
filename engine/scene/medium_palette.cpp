#include "scene/medium_palette.h"
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include "math/rng.h"
#include "media/diffusion_dipole.h"

namespace photon {

namespace {
constexpr int kValues = MediumPalettes::kSteps + 1;  // reflectances 0, 1/kSteps, ..., 1 per channel
}

MediumPalettes::MediumPalettes(std::vector<MediumDescription>& media) {
    const size_t count = media.size();
    bool anyTextured = false;
    for (const MediumDescription& m : media) anyTextured = anyTextured || (m.reflectance && m.reflectance->reflectance.textured());
    if (!anyTextured) return;
    first_.assign(count, -1);
    reflectance_.assign(count, nullptr);
    for (size_t i = 0; i < count; ++i) {
        if (!media[i].reflectance || !media[i].reflectance->reflectance.textured()) continue;
        const MediumDescription parent = media[i];  // a copy: media grows below
        const MediumReflectance& r = *parent.reflectance;
        first_[i] = int32_t(media.size());
        reflectance_[i] = parent.reflectance.get();
        // Each channel's coefficients at each step, then every combination, red slowest.
        std::array<ScatteringCoefficients, kValues> step;
        for (int k = 0; k < kValues; ++k)
            step[size_t(k)] = coefficientsOfReflectance(Color(float(k) / MediumPalettes::kSteps), r.meanFreePath, r.boundaryIor);
        media.reserve(media.size() + size_t(kValues) * kValues * kValues);
        for (int red = 0; red < kValues; ++red)
            for (int green = 0; green < kValues; ++green)
                for (int blue = 0; blue < kValues; ++blue) {
                    MediumDescription m;
                    m.name = parent.name;
                    m.g = parent.g;
                    m.density = parent.density;
                    m.subsurface = parent.subsurface;
                    m.reflectance = parent.reflectance;
                    const int k[3] = {red, green, blue};
                    for (int c = 0; c < 3; ++c) {
                        m.absorption[c] = step[size_t(k[c])].absorption[c];
                        m.scattering[c] = step[size_t(k[c])].scattering[c];
                    }
                    media.push_back(std::move(m));
                }
    }
    family_.resize(media.size());
    for (size_t i = 0; i < count; ++i) family_[i] = int32_t(i);
    for (size_t i = 0; i < count; ++i)
        if (first_[i] >= 0)
            std::fill(family_.begin() + first_[i], family_.begin() + first_[i] + kValues * kValues * kValues, int32_t(i));
}

int32_t MediumPalettes::entered(int32_t medium, const TexturePoint& at) const {
    const Color r = reflectance_[size_t(medium)]->reflectance.eval(at);
    // The dither's number: the point's hash, so that every ray entering there agrees.
    uint64_t h = 0;
    for (float f : {at.p.x, at.p.y, at.p.z}) h = mix64<uint64_t>(h ^ std::bit_cast<uint32_t>(f));
    const float u = static_cast<float>(h >> 40) * 0x1p-24f;
    int index = 0;
    for (int c = 0; c < 3; ++c) {
        // The step above with probability frac: u >= 1 - frac, which int(x + u) would be in
        // exact arithmetic; in float, x + u rounds up to the next step for u within 2^-20
        // of 1 even where frac is 0, so a reflectance on a step took its neighbour about once
        // in a million entries (found by tests/test_subsurface_reflectance.cpp under seed 8).
        const float x = std::clamp(r[c], 0.0f, 1.0f) * kSteps;
        const float below = std::floor(x), frac = x - below;
        const int step = int(below) + (u >= 1.0f - frac ? 1 : 0);
        index = index * kValues + std::min(step, kSteps);
    }
    return first_[size_t(medium)] + index;
}

}  // namespace photon
