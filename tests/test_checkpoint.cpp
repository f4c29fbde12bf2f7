// Checkpoints: stopping after some passes and resuming in a new renderer gives exactly the
// image of an uninterrupted render; checkpoints of other scenes or settings are refused.
#include <gtest/gtest.h>
#include <cstring>
#include <limits>
#include <sstream>
#include "integrators/common/checkpoint.h"
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
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
    SceneDescription otherDiscs = glassBox(GetParam());
    otherDiscs.render.autoRadiusPhotons = 16;
    for (SceneDescription* d : {&otherSeed, &otherSize, &otherDiscs}) {
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

std::string checkpointAfterOnePass(IntegratorKind kind) {
    CancelToken cancel;
    Renderer first(Scene::build(glassBox(kind)));
    EXPECT_TRUE(first.renderPass(cancel));
    std::stringstream saved;
    first.saveCheckpoint(saved);
    return saved.str();
}

// A refused checkpoint leaves the renderer as it was: it renders what a fresh one does.
void expectRefusedAndUntouched(IntegratorKind kind, const std::string& bytes) {
    Renderer r(Scene::build(glassBox(kind)));
    std::stringstream in(bytes);
    EXPECT_THROW(r.restoreCheckpoint(in), CheckpointError);
    EXPECT_EQ(r.integrator().passesDone(), 0);
    EXPECT_EQ(r.progress().photonsTraced, 0);
}

TEST_P(Checkpoint, DamagedOrCutShortFilesAreRefused) {
    const std::string bytes = checkpointAfterOnePass(GetParam());
    // One flipped bit anywhere (header, pixel data, seal), and every cut, is caught.
    for (size_t at = 0; at < bytes.size(); at += 1 + bytes.size() / 97) {
        std::string damaged = bytes;
        damaged[at] = static_cast<char>(damaged[at] ^ (1 << (at % 8)));
        expectRefusedAndUntouched(GetParam(), damaged);
        expectRefusedAndUntouched(GetParam(), bytes.substr(0, at));
    }
    expectRefusedAndUntouched(GetParam(), bytes + "x");
}

TEST_P(Checkpoint, WellSealedButImpossibleValuesAreRefused) {
    const std::string bytes = checkpointAfterOnePass(GetParam());
    const std::string body(unsealCheckpoint(bytes));
    // Layout: photons (8 bytes), seconds (8), header (8 magic, 4 version, 16 key), passes (4).
    constexpr size_t kPassesAt = 8 + 8 + 8 + 4 + sizeof(CheckpointKey);
    auto withBytes = [&](size_t at, const void* value, size_t n) {
        std::string changed = body;
        std::memcpy(changed.data() + at, value, n);
        return sealCheckpoint(changed);
    };
    const int negativePasses = -3;
    const int64_t negativePhotons = -1;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    expectRefusedAndUntouched(GetParam(), withBytes(kPassesAt, &negativePasses, sizeof negativePasses));
    expectRefusedAndUntouched(GetParam(), withBytes(0, &negativePhotons, sizeof negativePhotons));
    // The first pixel value after the pass count: a sum of light or a statistic.
    expectRefusedAndUntouched(GetParam(), withBytes(kPassesAt + 4, &nan, sizeof nan));
    expectRefusedAndUntouched(GetParam(), sealCheckpoint(body + "extra"));
    // And the untouched body, resealed, is still accepted.
    Renderer r(Scene::build(glassBox(GetParam())));
    std::stringstream in(sealCheckpoint(body));
    r.restoreCheckpoint(in);
    EXPECT_EQ(r.integrator().passesDone(), 1);
}

INSTANTIATE_TEST_SUITE_P(Integrators, Checkpoint, ::testing::Values(IntegratorKind::Sppm, IntegratorKind::Path,
                                                                          IntegratorKind::Radiosity));

}  // namespace
}  // namespace photon
