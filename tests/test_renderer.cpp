// The engine's face: progress per pass, cancellation inside a pass, time limits, snapshots.
#include <gtest/gtest.h>
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
    // A pass with many photons that sees the token set from its first work chunk on: it must
    // stop at once, however many threads would share its work, and leave the state as after
    // the last finished pass, so that the next pass makes what an uninterrupted render would.
    Renderer renderer(Scene::build(smallScene(1000, 2000000)));
    CancelToken none;
    ASSERT_TRUE(renderer.renderPass(none));
    Image afterOne = renderer.snapshot();
    CancelToken cancel;
    cancel.cancel();
    auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(renderer.renderPass(cancel));
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);  // stopped inside the pass: 2M photons take longer on 2 cores
    EXPECT_EQ(renderer.integrator().passesDone(), 1);
    EXPECT_TRUE(renderer.snapshot().rgb == afterOne.rgb);

    ASSERT_TRUE(renderer.renderPass(none));
    Renderer uninterrupted(Scene::build(smallScene(1000, 2000000)));
    ASSERT_TRUE(uninterrupted.renderPass(none));
    ASSERT_TRUE(uninterrupted.renderPass(none));
    EXPECT_TRUE(renderer.snapshot().rgb == uninterrupted.snapshot().rgb);
}

TEST(Renderer, CancelDuringARunStopsBeforeTheNextPass) {
    // The token set from the progress callback of pass 2: run() starts no further pass.
    Renderer renderer(Scene::build(smallScene(1000, 20000)));
    CancelToken cancel;
    Image afterTwo;
    RenderOutcome outcome = renderer.run(cancel, [&](const RenderProgress& p) {
        if (p.pass == 2) {
            afterTwo = renderer.snapshot();
            cancel.cancel();
        }
    });
    EXPECT_EQ(outcome, RenderOutcome::Cancelled);
    EXPECT_EQ(renderer.integrator().passesDone(), 2);
    EXPECT_TRUE(renderer.snapshot().rgb == afterTwo.rgb);
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
