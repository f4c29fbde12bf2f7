#include "integrators/common/lights_in_view.h"
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include "integrators/common/shading.h"

namespace photon {
namespace {

// Whether the camera ray through film position (x, y) first lands on a surface that emits
// toward it.
bool showsLight(const Scene& scene, float x, float y) {
    const Ray ray = scene.camera().generateRay(x, y, {0.5f, 0.5f});
    Color beta(1.0f);
    int32_t medium = scene.description().camera.medium;
    SurfaceHit hit;
    if (castPastBoundaries(scene, ray, beta, medium, hit) != RayEnd::Surface) return false;
    return !isBlack(scene.emitted(hit, -ray.d));
}

}  // namespace

void LightsInView::find() const {
    if (!scene_->hasEmittingShapes()) return;
    const int width = width_, height = height_;
    wordsPerRow_ = (static_cast<size_t>(width) + 63) / 64;
    rows_.assign(wordsPerRow_ * static_cast<size_t>(height), 0);
    // Blocks of 8 to 16 rows, each tracing the corners of its rows once (a block's last
    // corner row is traced again by the next block: at most 1/8 more corner rays).
    constexpr int kRowsPerBlock = 16;
    tbb::parallel_for(tbb::blocked_range<int>(0, height, kRowsPerBlock), [&](const tbb::blocked_range<int>& block) {
        const size_t corners = static_cast<size_t>(width) + 1;
        std::vector<uint8_t> above(corners), below(corners);
        auto cornerRow = [&](int y, std::vector<uint8_t>& row) {
            for (int x = 0; x <= width; ++x)
                row[x] = showsLight(*scene_, static_cast<float>(x), static_cast<float>(y));
        };
        cornerRow(block.begin(), above);
        for (int y = block.begin(); y < block.end(); ++y) {
            cornerRow(y + 1, below);
            uint64_t* bits = &rows_[static_cast<size_t>(y) * wordsPerRow_];
            for (int x = 0; x < width; ++x) {
                const bool light = above[x] || above[x + 1] || below[x] || below[x + 1] ||
                                   showsLight(*scene_, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                if (light) bits[x >> 6] |= uint64_t(1) << (x & 63);
            }
            std::swap(above, below);
        }
    });
}

}  // namespace photon
