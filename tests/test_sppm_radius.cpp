// The radius schedule of Hachisuka & Jensen 2009 (eq. 7-10), pixel by pixel, and the
// error against a converged reference falling as passes accumulate.
#include <gtest/gtest.h>
#include <cmath>
#include "integrators/path.h"
#include "integrators/sppm.h"
#include "render.h"
#include "test_support.h"

namespace photon {
namespace {

SceneDescription smallCornell(int resolution) {
    return test::exampleScene("cornell-box", resolution, 64, 20000, 3);
}

TEST(SppmRadius, FollowsTheProgressiveSchedule) {
    const int res = 24;
    auto scene = Scene::build(smallCornell(res));
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
