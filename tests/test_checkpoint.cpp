// Checkpoints: stopping after some passes and resuming in a new renderer gives exactly the
// image of an uninterrupted render; checkpoints of other scenes or settings are refused.
#include <gtest/gtest.h>
#include <sstream>
#include "integrators/checkpoint.h"
#include "render.h"
#include "test_support.h"

namespace photon {
namespace {

SceneDescription glassBox(IntegratorKind kind) {
    SceneDescription d = test::exampleScene("cornell-glass", 24, 6, 10000, 11);
    d.render.integrator = kind;
    return d;
}

class Checkpoint : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(Checkpoint, ResumedRenderIsBitIdenticalToUninterrupted) {
    CancelToken cancel;
    Renderer whole(Scene::build(glassBox(GetParam())));
    whole.run(cancel);

    std::stringstream saved;
    {
        Renderer first(Scene::build(glassBox(GetParam())));
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(first.renderPass(cancel));
        first.saveCheckpoint(saved);
    }
    Renderer resumed(Scene::build(glassBox(GetParam())));
    resumed.restoreCheckpoint(saved);
    EXPECT_EQ(resumed.progress().pass, 3);
    EXPECT_EQ(resumed.run(cancel), RenderOutcome::Completed);
    EXPECT_EQ(resumed.integrator().passesDone(), 6);
    EXPECT_EQ(resumed.progress().photonsTraced, whole.progress().photonsTraced);
    EXPECT_TRUE(resumed.snapshot().rgb == whole.snapshot().rgb);
}

TEST_P(Checkpoint, OtherSettingsOrSizeAreRefused) {
    CancelToken cancel;
    Renderer first(Scene::build(glassBox(GetParam())));
    ASSERT_TRUE(first.renderPass(cancel));
    std::stringstream saved;
    first.saveCheckpoint(saved);
    const std::string bytes = saved.str();

    SceneDescription otherSeed = glassBox(GetParam());
    otherSeed.render.seed = 12;
    SceneDescription otherSize = glassBox(GetParam());
    otherSize.camera.width = 25;
    for (SceneDescription* d : {&otherSeed, &otherSize}) {
        Renderer r(Scene::build(*d));
        std::stringstream in(bytes);
        EXPECT_THROW(r.restoreCheckpoint(in), CheckpointError);
        EXPECT_EQ(r.integrator().passesDone(), 0);  // untouched
    }
    Renderer r(Scene::build(glassBox(GetParam())));
    std::stringstream truncated(bytes.substr(0, bytes.size() / 2));
    EXPECT_THROW(r.restoreCheckpoint(truncated), CheckpointError);
    std::stringstream garbage("not a checkpoint at all, just some text");
    EXPECT_THROW(r.restoreCheckpoint(garbage), CheckpointError);
    EXPECT_EQ(r.integrator().passesDone(), 0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, Checkpoint, ::testing::Values(IntegratorKind::Sppm, IntegratorKind::Path,
                                                                          IntegratorKind::Radiosity));

}  // namespace
}  // namespace photon
