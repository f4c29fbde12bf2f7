// render.bands: a pass's camera paths, grid and photons one band of rows at a time, each band
// tracing the pass's photons again, so that a large frame's visible points and grid need
// not all be in memory at once. Photons are the same in every band and their sums are
// integers, so the image is the one a single band makes, bit for bit.
#include <gtest/gtest.h>
#include <chrono>
#include <thread>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "integrators/sppm/sppm.h"
#include "scene/scene.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon::sppm_bands_tests {
namespace {

// The glass-sphere Cornell box at 24 x 33: 33 rows, so that bands do not divide them evenly.
SceneDescription glassBox(int bands, int passes = 5) {
    SceneDescription d = test::exampleScene("cornell-glass", 24, passes, 20000, 3);
    d.camera.height = 33;
    d.render.bands = bands;
    d.render.adaptivePhotons = false;
    return d;
}

struct Rendered {
    Image image;
    RenderProgress progress;
};

Rendered render(SceneDescription d) {
    Renderer r(Scene::build(std::move(d)));
    CancelToken cancel;
    EXPECT_EQ(r.run(cancel), RenderOutcome::Completed);
    return {r.snapshot(), r.progress()};
}

void expectSameImageInBands(const SceneDescription& d, std::initializer_list<int> bandCounts) {
    const Rendered one = render(d);
    EXPECT_GT(test::meanOver(one.image, 0, 0, 24, 33).y, 0.05f);  // there is light to get wrong
    for (int bands : bandCounts) {
        SCOPED_TRACE(std::to_string(bands) + " bands");
        SceneDescription banded = d;
        banded.render.bands = bands;
        const Rendered many = render(banded);
        EXPECT_TRUE(many.image.rgb == one.image.rgb);
        EXPECT_EQ(many.progress.photonsTraced, one.progress.photonsTraced);
        // Every band traces the pass's photons: the rays are the bands' times one band's,
        // and the photons accepted by visible points add up to one band's.
        EXPECT_EQ(many.progress.lastPass.photonRays, bands * one.progress.lastPass.photonRays);
        EXPECT_EQ(many.progress.lastPass.gatherHits, one.progress.lastPass.gatherHits);
        EXPECT_EQ(many.progress.lastPass.cameraRays, one.progress.lastPass.cameraRays);
    }
}

// Bands of a row each too: the grid then holds 24 discs.
TEST(SppmBands, PerPixelScheduleGivesTheOneBandImage) { expectSameImageInBands(glassBox(1), {3, 33}); }

TEST(SppmBands, GlobalScheduleGivesTheOneBandImage) {
    SceneDescription d = glassBox(1);
    d.render.radiusSchedule = RadiusSchedule::Global;
    expectSameImageInBands(d, {4});
}

TEST(SppmBands, LightweightGivesTheOneBandImage) {
    SceneDescription d = glassBox(1);
    d.render.lightweight = true;
    expectSameImageInBands(d, {4});
}

TEST(SppmBands, PhotonGuidingGivesTheOneBandImage) {
    SceneDescription d = glassBox(1, 2);
    d.render.photonGuiding = true;  // its training passes in bands too
    expectSameImageInBands(d, {3});
}

// With adaptive photon counts the bands' photon rays are part of what a photon costs, so
// the counts chosen may differ from one band's; the render is still the same for a seed on
// any number of threads.
TEST(SppmBands, AdaptivePhotonsInBandsAreDeterministic) {
    SceneDescription d = glassBox(3, 10);
    d.render.adaptivePhotons = true;
    const Image one = test::renderWithThreads(d, 1), two = test::renderWithThreads(d, 2);
    EXPECT_TRUE(one.rgb == two.rgb);
}

// A band holds ceil(rows / bands) rows, so 8 bands asked of 33 rows hold 5 rows each and
// there are 7 of them; more bands than rows give a row each.
TEST(SppmBands, BandsHoldWholeRowsAsEvenlyAsTheyCan) {
    for (auto [asked, made] : {std::pair{1, 1}, {2, 2}, {4, 4}, {5, 5}, {8, 7}, {33, 33}, {100, 33}}) {
        SppmIntegrator sppm(Scene::build(glassBox(asked)));
        EXPECT_EQ(sppm.bandCount(), made) << asked << " bands asked for";
    }
}

TEST(SppmBands, SceneFilesSayAutoOrACount) {
    test::Json doc = test::fullScene();
    EXPECT_EQ(test::load(doc).render.bands, 0);  // "auto" when not given
    doc["render"]["bands"] = "auto";
    EXPECT_EQ(test::load(doc).render.bands, 0);
    doc["render"]["bands"] = 6;
    EXPECT_EQ(test::load(doc).render.bands, 6);
}

// Resuming a checkpoint taken in one band count into another gives the same image: bands are
// how a pass is computed, not what it computes, so they are not part of the checkpoint's key.
TEST(SppmBands, ACheckpointResumesInOtherBands) {
    CancelToken cancel;
    const Rendered whole = render(glassBox(1, 6));
    std::stringstream saved;
    {
        Renderer first(Scene::build(glassBox(1, 6)));
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(first.renderPass(cancel));
        first.saveCheckpoint(saved);
    }
    Renderer resumed(Scene::build(glassBox(4, 6)));
    resumed.restoreCheckpoint(saved);
    EXPECT_EQ(resumed.run(cancel), RenderOutcome::Completed);
    EXPECT_TRUE(resumed.snapshot().rgb == whole.image.rgb);
}

// The statistics take each band's results while the next band is traced, so a pass that
// has begun to change them goes on to its end when cancelled: renderPass either leaves the
// render as it was (false) or adds the whole pass (true), never a part. Cancels come at
// delays stepping through the passes, before, inside and after their bands; whichever way
// each falls, the image after it must be the one an uncancelled render has after as many
// passes. (Passes here take 3-4 ms, 5-10 times that under the sanitizers: the delays are
// in units of the pass's own time, measured first.)
void expectPassesAddedWholeOrNotAtAll(SceneDescription d) {
    constexpr int kPasses = 6;
    d.render.passes = kPasses;
    std::vector<Image> after;  // after k passes, uncancelled
    std::chrono::duration<double> passTime{};  // an uncancelled pass's, here (sanitizers slow it 5-10x)
    {
        SppmIntegrator whole(Scene::build(SceneDescription(d)));
        CancelToken never;
        after.push_back(whole.snapshot());
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < kPasses; ++k) {
            ASSERT_TRUE(whole.renderPass(never));
            after.push_back(whole.snapshot());
        }
        passTime = (std::chrono::steady_clock::now() - start) / kPasses;
    }
    SppmIntegrator sppm(Scene::build(std::move(d)));
    for (int attempt = 0; sppm.passesDone() < kPasses; ++attempt) {
        ASSERT_LT(attempt, 2000);
        CancelToken cancel;
        // From no delay to twice a pass's time, in sixteenths: some cancels come before a
        // pass's first band ends, some inside it, some after it.
        const auto delay = passTime * ((attempt % 16) / 8.0);
        std::thread canceller([&] {
            std::this_thread::sleep_for(delay);
            cancel.cancel();
        });
        const int before = sppm.passesDone();
        const bool added = sppm.renderPass(cancel);
        canceller.join();
        ASSERT_EQ(sppm.passesDone(), before + (added ? 1 : 0));
        ASSERT_TRUE(sppm.snapshot().rgb == after[static_cast<size_t>(sppm.passesDone())].rgb)
            << "after attempt " << attempt << ", " << sppm.passesDone() << " passes";
    }
}

TEST(SppmBands, ACancelledPassIsAddedWholeOrNotAtAll) { expectPassesAddedWholeOrNotAtAll(glassBox(3)); }

TEST(SppmBands, ACancelledGlobalPassIsAddedWholeOrNotAtAll) {
    SceneDescription d = glassBox(3);
    d.render.radiusSchedule = RadiusSchedule::Global;
    expectPassesAddedWholeOrNotAtAll(std::move(d));
}

}  // namespace
}  // namespace photon::sppm_bands_tests
