// Helpers shared by the engine tests.
#pragma once
#include <filesystem>
#include <string>

namespace photon::test {

// Absolute path of a file in the source tree, e.g. sourcePath("scenes/cornell-box.json").
inline std::filesystem::path sourcePath(const std::string& relative) {
    return std::filesystem::path(PHOTON_SOURCE_DIR) / relative;
}

}  // namespace photon::test

#include <cmath>
#include <photon/image.h>
#include "scene/scene_loader.h"

namespace photon::test {

// An example scene from scenes/ at a small square resolution, with the render settings the
// tests vary most; other settings stay as the file has them.
inline SceneDescription exampleScene(const std::string& name, int resolution, int passes, int64_t photonsPerPass,
                                     uint64_t seed) {
    SceneDescription d = loadSceneFile(sourcePath("scenes/" + name + ".json"));
    d.camera.width = d.camera.height = resolution;
    d.render.passes = passes;
    d.render.photonsPerPass = photonsPerPass;
    d.render.seed = seed;
    return d;
}

// Renders all the scene's passes; the snapshot after the last.
Image renderImage(SceneDescription d);

// The small scene a material's SPPM image is held to the path tracer's on: the Cornell box
// (scenes/cornell-box.json) at `resolution` with its two blocks made of `material`, or,
// with `sphere`, the blocks replaced by one sphere of it (radius 0.3, on the floor).
SceneDescription cornellBoxWith(MaterialPtr material, int resolution, bool sphere = false);
// Image means of the scene by the path tracer and by SPPM, with the passes and photons
// given, at maximum depth 64 (transport the two see alike).
struct PathAndSppmMeans {
    Color path, sppm;
};
PathAndSppmMeans renderPathAndSppm(SceneDescription d, int pathPasses, int sppmPasses, int64_t photonsPerPass);
// The same with at most `threads` oneTBB threads (determinism tests).
Image renderWithThreads(SceneDescription d, int threads);

// Mean colour over the pixel rectangle [x0, x1) x [y0, y1).
inline Color meanOver(const Image& image, int x0, int y0, int x1, int y1) {
    Color sum(0.0f);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += image.at(x, y);
    return sum / static_cast<float>((x1 - x0) * (y1 - y0));
}

// Component-wise closeness of two Vec3 (or Color) values, in a gtest test body; Vec3
// must name photon::Vec3 where it is used.
#define EXPECT_VEC3_NEAR(a, b, tol)       \
    do {                                  \
        Vec3 a_ = (a), b_ = (b);          \
        EXPECT_NEAR(a_.x, b_.x, tol);     \
        EXPECT_NEAR(a_.y, b_.y, tol);     \
        EXPECT_NEAR(a_.z, b_.z, tol);     \
    } while (0)


}  // namespace photon::test
