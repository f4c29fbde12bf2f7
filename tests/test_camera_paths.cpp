// render.adaptive_camera_paths (integrators/sppm/camera_paths.h): SPPM's pixels trace as many
// camera paths a pass as their camera-side variance and the pass's costs make worth it. The
// counts follow the formula, the image stays the same with less noise, and the render stays
// deterministic through threads and checkpoints.
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <sstream>
#include "integrators/sppm/camera_paths.h"
#include <photon/render.h>
#include "integrators/common/checkpoint.h"
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "test_support.h"

namespace photon {
namespace {

// A 3 x 3 image: every pixel traced `paths` paths of luminance 1 and 3 alike (mean 2,
// variance 1), except the centre's, whose paths brought 2 each (variance 0).
struct Taught {
    AdaptiveCameraPaths paths{3, 3};
    float direct[9];
};
Taught taught(float paths) {
    Taught t;
    for (size_t i = 0; i < 9; ++i) {
        const float squares = i == 4 ? paths * 4.0f : paths * 0.5f * (1.0f + 9.0f);
        t.paths.add(i, paths, squares);
        t.direct[i] = 2.0f * paths;
    }
    return t;
}

TEST(AdaptiveCameraPaths, OnePathUntilTheFirstDecision) {
    const Taught t = taught(4);
    EXPECT_FLOAT_EQ(t.paths.pathsAt(4, [&](size_t j) { return t.direct[j]; }), 1.0f);
    EXPECT_FLOAT_EQ(t.paths.pathsTraced(4), 4.0f);
}

TEST(AdaptiveCameraPaths, PathsFollowTheStandardDeviationTimesTheScale) {
    Taught t = taught(4);
    // A pass of cost C = 800 rays, a path 2 rays, pass variance V = 25 summed over pixels:
    // scale kGain sqrt(C / (c V)) = kGain sqrt(800 / 50) = 4 kGain.
    t.paths.decide(800, 2, 25);
    const auto direct = [&](size_t j) { return t.direct[j]; };
    const float scale = 4.0f * AdaptiveCameraPaths::kGain;
    // The centre reads its eight neighbours' variance 1 and its own 0: 8 / 9, s = 0.943.
    EXPECT_NEAR(t.paths.pathsAt(4, direct), scale * std::sqrt(8.0f / 9.0f), 1e-5f);
    // A corner reads itself and three neighbours, the centre among them: 3 / 4.
    EXPECT_NEAR(t.paths.pathsAt(0, direct), scale * std::sqrt(3.0f / 4.0f), 1e-5f);
    // Within [1, kMaxPaths].
    t.paths.decide(800 * 100, 2, 25);
    EXPECT_FLOAT_EQ(t.paths.pathsAt(0, direct), AdaptiveCameraPaths::kMaxPaths);
    t.paths.decide(800, 2, 25 * 100);
    EXPECT_FLOAT_EQ(t.paths.pathsAt(0, direct), 1.0f);
}

TEST(AdaptiveCameraPaths, CheckpointBlockRoundTripsAndIsOptional) {
    Taught t = taught(4);
    t.paths.decide(800, 2, 25);
    const auto direct = [&](size_t j) { return t.direct[j]; };
    std::stringstream s;
    t.paths.save(s);
    s << "next";
    AdaptiveCameraPaths restored(3, 3);
    restored.restore(s, 4, direct);
    EXPECT_FLOAT_EQ(restored.pathsAt(0, direct), t.paths.pathsAt(0, direct));
    EXPECT_FLOAT_EQ(restored.pathsTraced(4), 4.0f);
    std::string rest;
    s >> rest;
    EXPECT_EQ(rest, "next");
    // Written before the block existed: one path a pass so far, of a variance not known, and
    // the stream where it was.
    std::stringstream old("halves");
    restored.restore(old, 3, direct);
    EXPECT_FLOAT_EQ(restored.pathsTraced(4), 3.0f);
    EXPECT_FLOAT_EQ(restored.pathsAt(0, direct), 1.0f);
    old >> rest;
    EXPECT_EQ(rest, "halves");
    // A pixel whose squares passed a float's range still writes a checkpoint that restores.
    AdaptiveCameraPaths huge(3, 3);
    for (size_t i = 0; i < 9; ++i) huge.add(i, 4, std::numeric_limits<float>::infinity());
    std::stringstream hugeState;
    huge.save(hugeState);
    EXPECT_NO_THROW(restored.restore(hugeState, 4, direct));
    // Fewer paths than the render's passes: damaged.
    std::stringstream again;
    t.paths.save(again);
    EXPECT_THROW(restored.restore(again, 5, direct), CheckpointError);
}

// An example scene at 96 x 96 with fixed photon counts.
SceneDescription exampleWith(const char* name, bool adaptive, uint64_t seed, int passes) {
    SceneDescription d = test::exampleScene(name, 96, passes, 20'000, seed);
    d.render.adaptivePhotons = false;
    d.render.maxDepth = 64;
    d.render.adaptiveCameraPaths = adaptive;
    return d;
}

TEST(AdaptiveCameraPaths, TheFirstPassesAreThoseOfOnePathAPixel) {
    // The first decision falls after pass 4: till then the image is the one-path image, bit
    // for bit, and the camera traced a path a pixel.
    Renderer on(Scene::build(exampleWith("cornell-glass", true, 5, 4)));
    Renderer off(Scene::build(exampleWith("cornell-glass", false, 5, 4)));
    on.run(CancelToken{});
    off.run(CancelToken{});
    EXPECT_TRUE(on.snapshot().rgb == off.snapshot().rgb);
    EXPECT_EQ(on.integrator().lastPassStats().cameraPaths, 96 * 96);
    // Then pixels trace more.
    on.renderPass(CancelToken{});
    EXPECT_GT(on.integrator().lastPassStats().cameraPaths, 96 * 96);
}

TEST(AdaptiveCameraPaths, SameImageAsOnePathAPixelWithLessNoise) {
    // scenes/translucent-sheet.json: a sheet that lets light through in the Cornell box, whose
    // light, reflected and seen through the sheet, the camera paths find. 32 passes, two
    // seeds each: the same 16 x 16 block means within 3%, and less luminance noise.
    // Measured: 0.116 against 0.308 (seeds 3 and 4: 0.119 against 0.327).
    const int passes = 32;
    const Image on1 = test::renderImage(exampleWith("translucent-sheet", true, 1, passes));
    const Image on2 = test::renderImage(exampleWith("translucent-sheet", true, 2, passes));
    const Image off1 = test::renderImage(exampleWith("translucent-sheet", false, 1, passes));
    const Image off2 = test::renderImage(exampleWith("translucent-sheet", false, 2, passes));
    test::expectSameBlockMeans(on1, on2, off1, off2, 16, 0.03f);
    const double onNoise = test::relativeNoiseOfLuminance(on1, on2);
    const double offNoise = test::relativeNoiseOfLuminance(off1, off2);
    EXPECT_LT(onNoise, 0.6 * offNoise) << onNoise << " against " << offNoise;
}

TEST(AdaptiveCameraPaths, BitIdenticalOnAnyThreadCountAndThroughACheckpoint) {
    const SceneDescription d = exampleWith("cornell-glass", true, 3, 12);
    const Image one = test::renderWithThreads(d, 1), two = test::renderWithThreads(d, 2);
    EXPECT_TRUE(one.rgb == two.rgb);
    EXPECT_FALSE(one.rgb == test::renderImage(exampleWith("cornell-glass", false, 3, 12)).rgb);
    const std::unique_ptr<Renderer> resumed = test::resumedAfter(d, 8);
    EXPECT_TRUE(resumed->snapshot().rgb == two.rgb);
}

}  // namespace
}  // namespace photon
