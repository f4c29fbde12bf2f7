// With a fixed seed the image is bit-identical whatever the number of threads: random
// streams are keyed by pixel, photon and pass, and photon sums are integers.
#include <gtest/gtest.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon::sppm_determinism_tests {
namespace {

Image renderWithThreads(int threads, IntegratorKind kind,
                        PixelFilterDescription::Kind filter = PixelFilterDescription::Kind::Box) {
    SceneDescription d = test::exampleScene("cornell-glass", 48, 3, 30000, 42);
    d.render.integrator = kind;
    d.camera.filter.kind = filter;
    d.camera.filter.radius = {PixelFilterDescription::defaultRadius(filter), PixelFilterDescription::defaultRadius(filter)};
    return test::renderWithThreads(std::move(d), threads);
}

TEST(Determinism, SppmSameSeedOneAndTwoThreadsGiveIdenticalPixels) {
    Image one = renderWithThreads(1, IntegratorKind::Sppm), two = renderWithThreads(2, IntegratorKind::Sppm);
    ASSERT_EQ(one.rgb.size(), two.rgb.size());
    size_t differing = 0;
    for (size_t i = 0; i < one.rgb.size(); ++i) differing += one.rgb[i] != two.rgb[i];
    EXPECT_EQ(differing, 0u);
    // And the image is not trivially empty: the glass box has light in it.
    EXPECT_GT(test::meanOver(one, 0, 0, 48, 48).y, 0.05f);
}

TEST(Determinism, PathSameSeedOneAndTwoThreadsGiveIdenticalPixels) {
    Image one = renderWithThreads(1, IntegratorKind::Path), two = renderWithThreads(2, IntegratorKind::Path);
    EXPECT_TRUE(one.rgb == two.rgb);
}

// Samples drawn from a pixel filter (here pbrt-v4's Gaussian, from a table) are keyed by
// pixel as the box's are.
TEST(Determinism, AFilteredImageIsTheSameOnOneAndTwoThreads) {
    using Kind = PixelFilterDescription::Kind;
    EXPECT_TRUE(renderWithThreads(1, IntegratorKind::Sppm, Kind::Gaussian).rgb ==
                renderWithThreads(2, IntegratorKind::Sppm, Kind::Gaussian).rgb);
    EXPECT_TRUE(renderWithThreads(1, IntegratorKind::Path, Kind::Mitchell).rgb ==
                renderWithThreads(2, IntegratorKind::Path, Kind::Mitchell).rgb);
    // And the filter is in effect: the Gaussian image differs from the box's.
    EXPECT_FALSE(renderWithThreads(2, IntegratorKind::Sppm, Kind::Gaussian).rgb ==
                 renderWithThreads(2, IntegratorKind::Sppm).rgb);
}

TEST(Determinism, DifferentSeedsGiveDifferentImages) {
    SceneDescription d = test::exampleScene("cornell-box", 16, 1, 5000, 1);
    auto render = [&](uint64_t seed) {
        SceneDescription copy = d;
        copy.render.seed = seed;
        Renderer r(Scene::build(std::move(copy)));
        CancelToken cancel;
        r.run(cancel);
        return r.snapshot();
    };
    EXPECT_FALSE(render(1).rgb == render(2).rgb);
}

// run() frees the hash grid when it stops; passes after it build the grid again and give the
// image of passes that never stopped, on both radius schedules.
TEST(Determinism, PassesAfterRunStoppedGiveTheUninterruptedImage) {
    for (RadiusSchedule schedule : {RadiusSchedule::PerPixel, RadiusSchedule::Global}) {
        SCOPED_TRACE(schedule == RadiusSchedule::Global ? "global" : "per-pixel");
        SceneDescription d = test::exampleScene("cornell-glass", 32, 2, 20000, 5);
        d.render.radiusSchedule = schedule;
        CancelToken cancel;
        Renderer stopped(Scene::build(SceneDescription(d)));
        ASSERT_EQ(stopped.run(cancel), RenderOutcome::Completed);
        Renderer straight(Scene::build(std::move(d)));
        for (int pass = 0; pass < 2; ++pass) ASSERT_TRUE(straight.renderPass(cancel));
        for (int pass = 0; pass < 2; ++pass) {
            ASSERT_TRUE(stopped.renderPass(cancel));
            ASSERT_TRUE(straight.renderPass(cancel));
        }
        EXPECT_EQ(stopped.progress().pass, 4);
        EXPECT_TRUE(stopped.snapshot().rgb == straight.snapshot().rgb);
        EXPECT_GT(test::meanOver(stopped.snapshot(), 0, 0, 32, 32).y, 0.05f);
    }
}

}  // namespace
}  // namespace photon::sppm_determinism_tests
