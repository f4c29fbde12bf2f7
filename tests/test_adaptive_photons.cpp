// render.adaptive_photons: the photons per pass chosen from the split of the error between
// camera paths and photons and their costs (integrators/sppm/photon_budget.h).
#include <gtest/gtest.h>
#include <cmath>
#include <sstream>
#include "integrators/sppm/photon_budget.h"
#include <photon/render.h>
#include "scene/scene.h"
#include "test_support.h"

namespace photon::adaptive_photons_tests {
namespace {

// Passes of N photons whose photons bring variance a / N and camera paths vc; a camera
// pass costs cc ray equivalents, a photon cp.
PhotonBudget budgetOf(int passes, int64_t n, double a, double cc, double cp) {
    PhotonBudget b;
    for (int i = 0; i < passes; ++i) b.add({n, a / static_cast<double>(n), cc, cp * static_cast<double>(n)});
    return b;
}

TEST(PhotonBudget, ChoosesTheCountWhereErrorTimesTimeIsLeast) {
    // E^2 T = (cc + N cp)(vc + a / N) is least at N* = sqrt(a cc / (cp vc)).
    const double a = 1000, vc = 0.01, cc = 1e6, cp = 2;
    const PhotonBudget b = budgetOf(8, 100'000, a, cc, cp);
    const double best = std::sqrt(a * cc / (cp * vc));  // 223,607
    EXPECT_EQ(b.next(100'000, vc + a / 100'000.0), std::llround(best));
    auto errorTimesTime = [&](double n) { return (cc + n * cp) * (vc + a / n); };
    EXPECT_LT(errorTimesTime(best), errorTimesTime(best * 1.2));
    EXPECT_LT(errorTimesTime(best), errorTimesTime(best / 1.2));
    // Passes at another count tell the same a: the answer does not depend on where it started.
    PhotonBudget mixed = budgetOf(4, 100'000, a, cc, cp);
    for (int i = 0; i < 4; ++i) mixed.add({300'000, a / 300'000.0, cc, cp * 300'000.0});
    const double meanPhotonVariance = (a / 100'000.0 + a / 300'000.0) / 2;
    EXPECT_EQ(mixed.next(300'000, vc + meanPhotonVariance), std::llround(best));
}

TEST(PhotonBudget, StepsAtMostFourfoldWithinItsBounds) {
    const PhotonBudget noPhotonNoise = budgetOf(4, 100'000, 0, 1e6, 2);
    EXPECT_EQ(noPhotonNoise.next(100'000, 0.01), 25'000);
    EXPECT_EQ(noPhotonNoise.next(2'000, 0.01), PhotonBudget::kMinPhotons);
    EXPECT_EQ(noPhotonNoise.next(300, 0.01), 300);  // started below the floor: held there
    // All the variance is the photons': the camera's is taken as a fiftieth of the whole.
    const PhotonBudget photonsOnly = budgetOf(4, 100'000, 1000, 1e6, 2);
    EXPECT_EQ(photonsOnly.next(100'000, 0.01), 400'000);
    EXPECT_EQ(PhotonBudget().next(123'456, 0.01), 123'456);  // nothing measured yet
}

TEST(PhotonBudget, DecidesAfterPass4AndEachDoublingOfThePasses) {
    std::vector<int64_t> decisions;
    for (int64_t p = 1; p <= 64; ++p)
        if (PhotonBudget::decidesAfter(p)) decisions.push_back(p);
    EXPECT_EQ(decisions, (std::vector<int64_t>{4, 8, 16, 32, 64}));
}

TEST(PhotonBudget, CheckpointRoundTripsAndRefusesNegativeSums) {
    const PhotonBudget b = budgetOf(8, 50'000, 300, 2e5, 3);
    std::stringstream s;
    b.save(s);
    PhotonBudget restored;
    restored.restore(s);
    EXPECT_EQ(restored.next(50'000, 0.02), b.next(50'000, 0.02));
    std::stringstream bad;
    const int64_t counts[2] = {8, 400'000};
    const double sums[4] = {1, -1, 1, 1};
    bad.write(reinterpret_cast<const char*>(counts), sizeof counts);
    bad.write(reinterpret_cast<const char*>(sums), sizeof sums);
    EXPECT_THROW(restored.restore(bad), std::runtime_error);
}

// The glass-sphere Cornell box at 32 x 32, starting from 200k photons a pass unless told.
SceneDescription glassBox(bool adaptive, int passes, int64_t photons = 200'000) {
    SceneDescription d = test::exampleScene("cornell-glass", 32, passes, photons, 7);
    d.render.adaptivePhotons = adaptive;
    return d;
}

// A render of `d` run to its end, and a checkpoint of another after `passes` passes.
struct WholeAndCheckpoint {
    Renderer whole;
    std::stringstream checkpoint;
};
WholeAndCheckpoint wholeAndCheckpoint(const SceneDescription& d, int passes) {
    CancelToken cancel;
    WholeAndCheckpoint r{Renderer(Scene::build(d)), {}};
    r.whole.run(cancel);
    Renderer first(Scene::build(d));
    for (int i = 0; i < passes; ++i) EXPECT_TRUE(first.renderPass(cancel));
    first.saveCheckpoint(r.checkpoint);
    return r;
}

TEST(AdaptivePhotons, ResumedAcrossADecisionIsBitIdentical) {
    CancelToken cancel;
    auto [whole, saved] = wholeAndCheckpoint(glassBox(true, 10), 6);
    Renderer resumed(Scene::build(glassBox(true, 10)));
    resumed.restoreCheckpoint(saved);
    EXPECT_EQ(resumed.run(cancel), RenderOutcome::Completed);
    EXPECT_EQ(resumed.progress().photonsTraced, whole.progress().photonsTraced);
    // The budget moved: the passes after the decisions at 4 and 8 traced fewer photons.
    EXPECT_LT(whole.progress().lastPass.photons, 200'000 / 4);
    EXPECT_TRUE(resumed.snapshot().rgb == whole.snapshot().rgb);
}

// Adaptive counts became the default after renders had been checkpointed with fixed ones:
// such a checkpoint, whose key is the settings' with adaptive_photons off, goes on with fixed
// counts to the image the fixed render would have made, and so do the checkpoints it writes.
TEST(AdaptivePhotons, ACheckpointWithFixedCountsGoesOnWithFixedCounts) {
    CancelToken cancel;
    auto [whole, saved] = wholeAndCheckpoint(glassBox(false, 10), 6);
    SceneDescription byDefault = glassBox(false, 10);
    byDefault.render.adaptivePhotons = RenderSettings{}.adaptivePhotons;
    ASSERT_TRUE(byDefault.render.adaptivePhotons);
    Renderer resumed(Scene::build(byDefault));
    resumed.restoreCheckpoint(saved);
    ASSERT_TRUE(resumed.renderPass(cancel));
    std::stringstream again;
    resumed.saveCheckpoint(again);
    Renderer resumedAgain(Scene::build(byDefault));
    resumedAgain.restoreCheckpoint(again);
    EXPECT_EQ(resumedAgain.run(cancel), RenderOutcome::Completed);
    EXPECT_EQ(resumedAgain.progress().photonsTraced, 10 * 200'000);
    EXPECT_TRUE(resumedAgain.snapshot().rgb == whole.snapshot().rgb);
    // A checkpoint of other settings is still refused.
    SceneDescription other = byDefault;
    other.render.seed = 8;
    Renderer refused(Scene::build(other));
    std::stringstream copy(saved.str());
    EXPECT_THROW(refused.restoreCheckpoint(copy), CheckpointError);
}

// Passes get cheaper or dearer as the count moves: the time left is reckoned from the
// passes since the last change, not from all of them.
TEST(AdaptivePhotons, TimeLeftFollowsThePassesSinceTheCountChanged) {
    CancelToken cancel;
    Renderer r(Scene::build(glassBox(true, 12)));
    std::vector<RenderProgress> seen;
    r.run(cancel, [&](const RenderProgress& p) { seen.push_back(p); });
    ASSERT_EQ(seen.size(), 12u);
    ASSERT_NE(seen[4].lastPass.photons, seen[3].lastPass.photons);  // the decision after pass 4
    int since = 0;  // the passes before the first at the current count
    for (int pass = 1; pass <= 12; ++pass) {
        if (pass > 1 && seen[pass - 1].lastPass.photons != seen[pass - 2].lastPass.photons) since = pass - 1;
        const double before = since ? seen[since - 1].elapsedSeconds : 0.0;
        const double perPass = (seen[pass - 1].elapsedSeconds - before) / (pass - since);
        EXPECT_NEAR(seen[pass - 1].etaSeconds, perPass * (12 - pass), 1e-9 * (1 + perPass * 12)) << "pass " << pass;
    }
}

// Passes of different photon counts are one estimate: tau / (pi R^2 N_emitted) counts the
// photons each pass traced. The image agrees with the render whose count stays fixed, over
// the whole frame and region by region (8 x 8 pixels), within what their noise allows.
TEST(AdaptivePhotons, ImageAgreesWithFixedPhotonsPerPass) {
    const Image adaptive = test::renderImage(glassBox(true, 384));
    const Image fixed = test::renderImage(glassBox(false, 384, 50'000));
    const double a = luminance(test::meanOver(adaptive, 0, 0, 32, 32)), f = luminance(test::meanOver(fixed, 0, 0, 32, 32));
    EXPECT_NEAR(a / f, 1.0, 0.01);
    double worst = 0;
    for (int y = 0; y < 32; y += 8)
        for (int x = 0; x < 32; x += 8) {
            const double ra = luminance(test::meanOver(adaptive, x, y, x + 8, y + 8));
            const double rf = luminance(test::meanOver(fixed, x, y, x + 8, y + 8));
            worst = std::max(worst, std::abs(ra / rf - 1.0));
        }
    EXPECT_LT(worst, 0.05);
    std::printf("whole frame: adaptive / fixed = %.4f; worst 8x8 region %.4f\n", a / f, worst);
}

TEST(AdaptivePhotons, OneAndTwoThreadsGiveIdenticalPixels) {
    const Image one = test::renderWithThreads(glassBox(true, 10), 1);
    const Image two = test::renderWithThreads(glassBox(true, 10), 2);
    EXPECT_TRUE(one.rgb == two.rgb);
}

}  // namespace
}  // namespace photon::adaptive_photons_tests
