// The radius schedule of Hachisuka & Jensen 2009 (eq. 7-10), pixel by pixel, and the
// error against a converged reference falling as passes accumulate.
#include <gtest/gtest.h>
#include <optional>
#include <cmath>
#include "integrators/path/path.h"
#include "integrators/sppm/sppm.h"
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon {
namespace {

SceneDescription smallCornell(int resolution) {
    return test::exampleScene("cornell-box", resolution, 64, 20000, 3);
}

TEST(SppmRadius, FollowsTheProgressiveSchedule) {
    const int res = 24;
    SceneDescription d = smallCornell(res);
    d.render.adaptiveRadius = false;  // alpha's schedule alone (test_adaptive_radius.cpp has the other)
    auto scene = Scene::build(std::move(d));
    SppmIntegrator sppm(scene);
    CancelToken cancel;
    ASSERT_TRUE(sppm.renderPass(cancel));
    const float alpha = scene->settings().alpha;
    int checked = 0;
    for (int pass = 1; pass < 6; ++pass) {
        std::vector<SppmIntegrator::PixelState> before;
        for (int y = 0; y < res; ++y)
            for (int x = 0; x < res; ++x) before.push_back(sppm.pixel(x, y));
        ASSERT_TRUE(sppm.renderPass(cancel));
        for (int y = 0; y < res; ++y)
            for (int x = 0; x < res; ++x) {
                const SppmIntegrator::PixelState& old = before[static_cast<size_t>(y) * res + x];
                const SppmIntegrator::PixelState& now = sppm.pixel(x, y);
                float m = static_cast<float>(sppm.lastPhotonCount(x, y));
                if (old.r2 == 0) continue;
                float expectedN = old.n + alpha * m;
                float expectedR2 = m > 0 ? old.r2 * (old.n + alpha * m) / (old.n + m) : old.r2;
                EXPECT_FLOAT_EQ(now.n, expectedN);
                EXPECT_NEAR(now.r2, expectedR2, 1e-6f * old.r2);
                EXPECT_LE(now.r2, old.r2);
                if (m > 0) ++checked;
            }
    }
    EXPECT_GT(checked, res * res);  // most pixels gathered photons in most passes
}

// The first pass's squared start radii of a 32 x 32 scene (the Cornell box unless given; 0
// where a pixel saw no surface).
std::vector<float> startingRadii2(float photonsPerDisc, int64_t photons, bool adaptiveRadius,
                                  std::optional<SceneDescription> scene = std::nullopt) {
    const int res = 32;
    SceneDescription d = scene ? std::move(*scene) : smallCornell(res);
    d.render.photonsPerPass = photons;
    d.render.autoRadiusPhotons = photonsPerDisc;
    d.render.adaptiveRadius = adaptiveRadius;
    SppmIntegrator sppm(Scene::build(std::move(d)));
    CancelToken cancel;
    EXPECT_TRUE(sppm.renderPass(cancel));
    std::vector<float> r2;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) r2.push_back(sppm.lastRadiusSquared(x, y));
    return r2;
}

// The auto radius: r = (distance travelled) (pixel angle) sqrt(k P / (pi photons)), with k
// photons per disc (render.auto_radius_photons), P pixels, clamped to 1.5-16 pixel
// footprints. The camera paths do not depend on k, so a pixel's starting radius squared
// scales with k where it is not clamped and not at all where it is.
TEST(SppmRadius, AutoRadiusScalesWithThePhotonsAskedForPerDisc) {
    const int res = 32;
    const int64_t photons = 100;
    // With alpha's schedule: the start radius is then k's alone.
    auto startingRadii2 = [&](float photonsPerDisc) { return photon::startingRadii2(photonsPerDisc, photons, false); };
    // 1024 pixels, 100 photons: k = 4 and 16 give 3.6 and 7.2 footprints (unclamped),
    // k = 0.05 and 0.1 give 0.40 and 0.57 (both clamped to 1.5).
    const std::vector<float> k4 = startingRadii2(4), k16 = startingRadii2(16);
    const std::vector<float> tiny = startingRadii2(0.05f), small = startingRadii2(0.1f);
    int seen = 0;
    for (size_t i = 0; i < k4.size(); ++i) {
        if (k4[i] == 0) continue;  // the pixel saw no surface
        ++seen;
        EXPECT_NEAR(k16[i] / k4[i], 4.0f, 4e-5f) << "pixel " << i;
        EXPECT_NEAR(small[i] / tiny[i], 1.0f, 1e-5f) << "pixel " << i;
        EXPECT_NEAR(tiny[i] / k4[i], 1.5f * 1.5f * kPi * photons / (4 * 1024.0f), 1e-5f) << "pixel " << i;
    }
    EXPECT_GT(seen, res * res / 2);
}

// With radii that follow the light a disc starts as wide as would hold kFlatPhotons (64) a
// pass, within [k's, 2.5 footprints]. On 1024 pixels k = 8 gives 1.5 footprints (the least)
// for 2,000, 5,000 and 10,000 photons; 64 photons would want sqrt(64 * 1024 / (pi n)) =
// 3.23 (so 2.5), 2.04 and 1.44 (so 1.5) footprints.
TEST(SppmRadius, RadiiThatFollowTheLightStartWiderWherePhotonsAreFew) {
    for (const auto& [photons, footprints] : {std::pair<int64_t, double>{2000, 2.5},
                                               {5000, std::sqrt(64 * 1024 / (kPi * 5000))},
                                               {10000, 1.5}}) {
        const std::vector<float> fixed = startingRadii2(8, photons, false), adaptive = startingRadii2(8, photons, true);
        int seen = 0;
        for (size_t i = 0; i < fixed.size(); ++i) {
            if (fixed[i] == 0) continue;
            ++seen;
            ASSERT_NEAR(adaptive[i] / fixed[i], footprints * footprints / 2.25, 1e-4) << photons << " photons, pixel " << i;
        }
        EXPECT_GT(seen, 512);
    }
}

// A ball in a medium shrinks by alpha's schedule either way (its photons' spread is not
// read), so it starts as it did: in the fog of cornell-fog the balls keep their radius while
// the discs on the walls behind start 2.5 footprints wide.
TEST(SppmRadius, BallsInAMediumStartAsAlphasScheduleHasThem) {
    auto fog = [] {
        SceneDescription d = test::exampleScene("cornell-fog", 32, 1, 2000, 1);
        d.render.volumePhotons = VolumePhotons::Always;
        return d;
    };
    const std::vector<float> fixed = startingRadii2(8, 2000, false, fog()), adaptive = startingRadii2(8, 2000, true, fog());
    int balls = 0, discs = 0;
    for (size_t i = 0; i < fixed.size(); ++i) {
        if (fixed[i] == 0) continue;
        const float ratio = adaptive[i] / fixed[i];
        if (std::abs(ratio - 1.0f) < 1e-5f) ++balls;
        else if (std::abs(ratio - 2.5f * 2.5f / 2.25f) < 1e-4f) ++discs;
        else ADD_FAILURE() << "pixel " << i << ": start radius squared " << ratio << " times alpha's";
    }
    EXPECT_GT(balls, 0);
    EXPECT_GT(discs, 0);
}

TEST(SppmRadius, ErrorFallsAsPassesGrow) {
    const int res = 32;
    SceneDescription ref = smallCornell(res);
    ref.render.integrator = IntegratorKind::Path;
    ref.render.passes = 4096;
    Renderer reference(Scene::build(std::move(ref)));
    CancelToken cancel;
    reference.run(cancel);
    Image truth = reference.snapshot();

    SceneDescription d = smallCornell(res);
    d.render.passes = 256;
    Renderer sppm(Scene::build(std::move(d)));
    std::vector<double> errors;
    for (int pass = 1; pass <= 256; ++pass) {
        ASSERT_TRUE(sppm.renderPass(cancel));
        if (pass == 4 || pass == 16 || pass == 64 || pass == 256) errors.push_back(rmse(sppm.snapshot(), truth));
    }
    for (size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << "after step " << i;
    // Consistency: at least a threefold drop from 4 to 256 passes.
    EXPECT_LT(errors.back(), errors.front() / 3) << errors.front() << " -> " << errors.back();
}

}  // namespace
}  // namespace photon
