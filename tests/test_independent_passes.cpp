// SPPM with the global radius schedule (render.radius_schedule "global"): its passes are
// independent estimates, so batches of them rendered by different renderers, added in any
// order, give bit for bit the image one renderer gives; the schedule against its product
// form; the mean against the per-pixel schedule's; checkpoints; the batches' binary form.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "test_support.h"

namespace photon {
namespace {

SceneDescription globalCornellBox(int passes, float initialRadius = 0) {
    SceneDescription d = test::exampleScene("cornell-box", 48, passes, 20000, 11);
    d.render.radiusSchedule = RadiusSchedule::Global;
    d.render.initialRadius = initialRadius;
    return d;
}

Renderer rendererOf(SceneDescription d) { return Renderer(Scene::build(std::move(d))); }

bool bitIdentical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST(IndependentPasses, BatchesFromManyRenderersInAnyOrderGiveTheOneRenderersImage) {
    const CancelToken never;
    Renderer one = rendererOf(globalCornellBox(8));
    ASSERT_TRUE(one.independentPasses());
    for (int i = 0; i < 8; ++i) ASSERT_TRUE(one.renderPass(never));

    // Three "workers" render passes 0-2, 3-3 and 4-7; the "coordinator" adds them last first,
    // each after a trip through the binary form.
    std::vector<PassSums> batches;
    for (auto [first, count] : {std::pair{0, 3}, std::pair{3, 1}, std::pair{4, 4}}) {
        Renderer worker = rendererOf(globalCornellBox(8));
        std::optional<PassSums> batch = worker.renderPasses(first, count, never);
        ASSERT_TRUE(batch);
        EXPECT_EQ(batch->first, first);
        EXPECT_EQ(batch->count, count);
        EXPECT_EQ(worker.integrator().passesDone(), 0);  // rendering a batch adds nothing
        batches.push_back(PassSums::decode(batch->encode()));
    }
    Renderer coordinator = rendererOf(globalCornellBox(8));
    for (auto b = batches.rbegin(); b != batches.rend(); ++b) coordinator.addPasses(*b);
    EXPECT_EQ(coordinator.integrator().passesDone(), 8);
    EXPECT_TRUE(bitIdentical(coordinator.rawSnapshot(), one.rawSnapshot()));

    // A different split gives the same image again; leaving a batch out does not.
    Renderer other = rendererOf(globalCornellBox(8));
    Renderer worker = rendererOf(globalCornellBox(8));
    other.addPasses(*worker.renderPasses(5, 3, never));
    other.addPasses(*worker.renderPasses(0, 5, never));
    EXPECT_TRUE(bitIdentical(other.rawSnapshot(), one.rawSnapshot()));
    Renderer missing = rendererOf(globalCornellBox(8));
    missing.addPasses(batches[0]);
    missing.addPasses(batches[2]);
    EXPECT_FALSE(bitIdentical(missing.rawSnapshot(), one.rawSnapshot()));
}

// With a fixed initial radius every visible point of pass i has r_i = r_1 sqrt(prod_{k=1}^{i}
// (k + alpha) / (k + 1)) (passes counted from 0 here), whatever came before: the product
// written out against the integrator's closed form.
TEST(IndependentPasses, RadiusFollowsTheGlobalSchedule) {
    const CancelToken never;
    const float r1 = 0.05f;
    SceneDescription d = globalCornellBox(64, r1);
    const double alpha = d.render.alpha;
    Renderer renderer = rendererOf(std::move(d));
    for (int pass : {0, 1, 9, 63}) {
        ASSERT_TRUE(renderer.renderPasses(pass, 1, never));
        double product = 1;
        for (int k = 1; k <= pass; ++k) product *= (k + alpha) / (k + 1.0);
        const double expected = r1 * std::sqrt(product);
        EXPECT_NEAR(renderer.integrator().lastPassStats().meanRadius, expected, 1e-6 * expected) << "pass " << pass;
    }
}

// The two schedules estimate the same image: means within 2% per channel (each within ~0.5%
// of its own converged value at these settings).
TEST(IndependentPasses, AgreeWithThePerPixelScheduleInTheMean) {
    SceneDescription global = globalCornellBox(48);
    SceneDescription perPixel = globalCornellBox(48);
    perPixel.render.radiusSchedule = RadiusSchedule::PerPixel;
    const Color a = test::meanOver(test::renderImage(std::move(global)), 0, 0, 48, 48);
    const Color b = test::meanOver(test::renderImage(std::move(perPixel)), 0, 0, 48, 48);
    std::printf("  mean: global %.4f %.4f %.4f, per pixel %.4f %.4f %.4f\n", a.x, a.y, a.z, b.x, b.y, b.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 0.02 * b[c]) << "channel " << c;
}

TEST(IndependentPasses, CheckpointsResumeToTheSameImage) {
    const CancelToken never;
    Renderer straight = rendererOf(globalCornellBox(5));
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(straight.renderPass(never));
    Renderer first = rendererOf(globalCornellBox(5));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(first.renderPass(never));
    std::stringstream checkpoint;
    first.saveCheckpoint(checkpoint);
    Renderer resumed = rendererOf(globalCornellBox(5));
    resumed.restoreCheckpoint(checkpoint);
    EXPECT_EQ(resumed.integrator().passesDone(), 3);
    for (int i = 0; i < 2; ++i) ASSERT_TRUE(resumed.renderPass(never));
    EXPECT_TRUE(bitIdentical(resumed.rawSnapshot(), straight.rawSnapshot()));
}

TEST(IndependentPasses, BinaryFormRoundTripsAndRefusesDamage) {
    const CancelToken never;
    Renderer renderer = rendererOf(globalCornellBox(4));
    PassSums batch = *renderer.renderPasses(2, 2, never);
    const std::string bytes = batch.encode();
    const size_t raw = (batch.values.size() + batch.oddLuminance.size()) * sizeof(int64_t);
    std::printf("  48x48, 2 passes: %zu bytes encoded, %zu raw (%.1f%%)\n", bytes.size(), raw,
                100.0 * double(bytes.size()) / double(raw));
    EXPECT_LT(bytes.size(), raw);
    PassSums back = PassSums::decode(bytes);
    EXPECT_EQ(back.first, 2);
    EXPECT_EQ(back.count, 2);
    EXPECT_EQ(back.width, 48);
    EXPECT_EQ(back.height, 48);
    EXPECT_EQ(back.values, batch.values);
    EXPECT_EQ(back.oddCount, 1);  // pass 3
    EXPECT_EQ(back.oddLuminance, batch.oddLuminance);

    auto refuses = [](std::string_view b, const std::string& message) {
        try {
            PassSums::decode(b);
            ADD_FAILURE() << "decoded: " << message;
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    };
    refuses(bytes.substr(0, 10), "pass sums: shorter than their header");
    refuses("XXXX" + bytes.substr(4), "pass sums: not pass sums");
    refuses(bytes.substr(0, bytes.size() - 8), "pass sums: damaged values");
    std::string wrongVersion = bytes;
    wrongVersion[4] = 9;
    refuses(wrongVersion, "pass sums: version 9, expected 2");

    PassSums small;
    small.width = small.height = 2;
    small.values.assign(12, 0);
    try {
        batch.add(small);
        ADD_FAILURE() << "added sums of another size";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "pass sums of 2x2 added to 48x48");
    }
}

TEST(IndependentPasses, PerPixelRendersHaveNone) {
    SceneDescription d = globalCornellBox(2);
    d.render.radiusSchedule = RadiusSchedule::PerPixel;
    Renderer renderer = rendererOf(std::move(d));
    EXPECT_FALSE(renderer.independentPasses());
    EXPECT_FALSE(renderer.renderPasses(0, 1, CancelToken{}));
    PassSums sums;
    EXPECT_THROW(renderer.addPasses(sums), std::logic_error);
}

}  // namespace
}  // namespace photon
