#include "integrators/common/lights_in_view.h"
#include <algorithm>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include "integrators/common/shading.h"

namespace photon {
namespace {

// The luminance emitted toward the camera where its ray through film position (x, y)
// first lands (0: none).
float emittedToward(const Scene& scene, float x, float y) {
    const Ray ray = scene.camera().generateRay(x, y, {0.5f, 0.5f});
    Color beta(1.0f);
    int32_t medium = scene.description().camera.medium;
    SurfaceHit hit;
    if (castPastBoundaries(scene, ray, beta, medium, hit) != RayEnd::Surface) return 0.0f;
    return luminance(scene.emitted(hit, -ray.d));
}

}  // namespace

uint8_t LightsInView::encode(float luminance) {
    if (!(luminance > 0)) return 0;
    const float steps = std::round(kStepsPerOctave * (std::log2(luminance) - kLeastOctave));
    return static_cast<uint8_t>(1.0f + std::clamp(steps, 0.0f, 254.0f));
}

float LightsInView::decode(uint8_t code) {
    if (code == 0) return 0.0f;
    return std::exp2(static_cast<float>(code - 1) / kStepsPerOctave + kLeastOctave);
}

void LightsInView::find() const {
    if (!scene_->hasEmittingShapes()) return;
    const int width = width_, height = height_;
    // Ranges of rows, each tracing the corners of its rows once (a range's last corner row is
    // traced again by the next range), each row's lit pixels kept apart until they are
    // joined in row order: the ranges oneTBB makes need not start at multiples of any size.
    constexpr int kRowsPerBlock = 16;
    std::vector<std::vector<uint32_t>> rowLit(static_cast<size_t>(height));
    tbb::parallel_for(tbb::blocked_range<int>(0, height, kRowsPerBlock), [&](const tbb::blocked_range<int>& block) {
        const size_t corners = static_cast<size_t>(width) + 1;
        std::vector<float> above(corners), below(corners);
        auto cornerRow = [&](int y, std::vector<float>& row) {
            for (int x = 0; x <= width; ++x) row[x] = emittedToward(*scene_, static_cast<float>(x), static_cast<float>(y));
        };
        cornerRow(block.begin(), above);
        for (int y = block.begin(); y < block.end(); ++y) {
            cornerRow(y + 1, below);
            std::vector<uint32_t>& lit = rowLit[static_cast<size_t>(y)];
            for (int x = 0; x < width; ++x) {
                const float centre = emittedToward(*scene_, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                if (const uint8_t code = encode(std::max({above[x], above[x + 1], below[x], below[x + 1], centre})))
                    lit.push_back(static_cast<uint32_t>(x) << 8 | code);
            }
            std::swap(above, below);
        }
    });
    rowStart_.assign(static_cast<size_t>(height) + 1, 0);
    for (int y = 0; y < height; ++y) rowStart_[y + 1] = rowStart_[y] + static_cast<uint32_t>(rowLit[y].size());
    lit_.reserve(rowStart_.back());
    for (const auto& lit : rowLit) lit_.insert(lit_.end(), lit.begin(), lit.end());
}

}  // namespace photon
