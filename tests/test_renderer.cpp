// The engine's face: progress per pass, cancellation inside a pass, time limits, snapshots.
#include <gtest/gtest.h>
#include <thread>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon {
namespace {

SceneDescription smallScene(int passes, int64_t photons) {
    return test::exampleScene("cornell-box", 32, passes, photons, 1);
}

TEST(Renderer, ReportsEveryPassWithCumulativePhotons) {
    Renderer renderer(Scene::build(smallScene(4, 1000)));
    std::vector<RenderProgress> seen;
    CancelToken cancel;
    EXPECT_EQ(renderer.run(cancel, [&](const RenderProgress& p) { seen.push_back(p); }), RenderOutcome::Completed);
    ASSERT_EQ(seen.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(seen[i].pass, i + 1);
        EXPECT_EQ(seen[i].totalPasses, 4);
        EXPECT_EQ(seen[i].photonsTraced, 1000 * (i + 1));
        EXPECT_GT(seen[i].meanRadius, 0.0);
        if (i > 0) EXPECT_LT(seen[i].meanRadius, seen[i - 1].meanRadius);  // radii only shrink
    }
    EXPECT_EQ(seen.back().etaSeconds, 0.0);
}

TEST(Renderer, CancelInsideAPassKeepsTheLastCompleteImage) {
    // A pass with many photons, cancelled while it runs.
    Renderer renderer(Scene::build(smallScene(1000, 2000000)));
    CancelToken none;
    ASSERT_TRUE(renderer.renderPass(none));
    Image afterOne = renderer.snapshot();
    CancelToken cancel;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        cancel.cancel();
    });
    auto start = std::chrono::steady_clock::now();
    RenderOutcome outcome = renderer.run(cancel);
    canceller.join();
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(outcome, RenderOutcome::Cancelled);
    EXPECT_LT(seconds, 5.0);  // stops within the pass, not after 1000 of them
    EXPECT_EQ(renderer.integrator().passesDone(), 1);
    EXPECT_TRUE(renderer.snapshot().rgb == afterOne.rgb);
}

TEST(Renderer, TimeLimitStopsAfterThePassThatCrossesIt) {
    SceneDescription d = smallScene(100000, 20000);
    d.render.timeLimitSeconds = 0.3;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    EXPECT_EQ(renderer.run(cancel), RenderOutcome::TimeLimit);
    EXPECT_GE(renderer.progress().elapsedSeconds, 0.3);
    EXPECT_LT(renderer.integrator().passesDone(), 100000);
    EXPECT_GT(renderer.integrator().passesDone(), 0);
}

TEST(Renderer, SnapshotBeforeAnyPassIsBlackAndSized) {
    Renderer renderer(Scene::build(smallScene(1, 100)));
    Image image = renderer.snapshot();
    EXPECT_EQ(image.width, 32);
    EXPECT_EQ(image.height, 32);
    for (float v : image.rgb) EXPECT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace photon
