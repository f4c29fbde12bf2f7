// render.adaptive_radius (integrators/sppm/adaptive_radius.h): each pixel's radius shrinks
// as far as its photons' spread says the bias asks for.
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>
#include "integrators/sppm/adaptive_radius.h"
#include "integrators/sppm/sppm.h"
#include <random>
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

// Photons over a disc of radius 1 with density 1 + b |x|^2 (drawn by rejection): their mean
// d^2 / r^2 is (1/2 + 4b/12) / (1 + 4b/8) exactly, and 48 (s - 1/2) / r^2 reads the
// Laplacian over the density at the centre, 4b, to first order in b r^2.
TEST(AdaptiveRadius, PhotonsSpreadReadsTheLaplacianOfTheirDensity) {
    for (const float b : {0.0f, 0.05f, -0.05f, 0.2f}) {
        std::mt19937 engine(7);
        std::uniform_real_distribution<float> uniform(0, 1);
        uint64_t units = 0;
        uint32_t photons = 0;
        const float most = 1 + std::max(b, 0.0f);
        while (photons < 1'000'000) {
            const float x = 2 * uniform(engine) - 1, y = 2 * uniform(engine) - 1, s = x * x + y * y;
            if (s > 1 || uniform(engine) * most > 1 + b * s) continue;
            units += static_cast<uint64_t>(s * PhotonSpread::kUnitsPerPhoton + 0.5f);
            ++photons;
        }
        const double exact = (0.5 + 4.0 * b / 12) / (1 + 4.0 * b / 8);
        const double mean = static_cast<double>(units) / (photons * double(PhotonSpread::kUnitsPerPhoton));
        // One million photons: the mean's standard error is 0.29 / 1000.
        EXPECT_NEAR(mean, exact, 1.2e-3) << "b " << b;
        EXPECT_NEAR(relativeLaplacian(static_cast<float>(mean), 1.0f), 4 * b, 0.06 + 0.1 * std::abs(4 * b)) << "b " << b;
        // The code a pass keeps is the mean within 1/508.
        EXPECT_NEAR(PhotonSpread::mean(PhotonSpread::of(static_cast<uint32_t>(units / 1000), photons / 1000)), mean,
                    1.0 / 508 + 1e-3);
    }
    EXPECT_EQ(PhotonSpread::of(0, 0), PhotonSpread::kUnknown);
    EXPECT_EQ(PhotonSpread::of(123, 1u << 21), PhotonSpread::kUnknown);  // past what 32 bits hold
    EXPECT_EQ(PhotonSpread::mean(PhotonSpread::of(1024 * 10, 10)), 127.0f / 254.0f);
}

// The balanced radius minimises (beta rho / 8)^2 + (r2 / n) / rho over rho.
TEST(AdaptiveRadius, BalancedRadiusMinimisesBiasSquaredPlusVariance) {
    for (const float beta : {1.0f, -30.0f, 400.0f})
        for (const float n : {10.0f, 1000.0f}) {
            const float r2 = 0.01f;
            auto error = [&](double rho) { return std::pow(beta * rho / 8, 2) + (r2 / n) / rho; };
            const float best = balancedRadiusSquared(r2, n, beta);
            EXPECT_NEAR(std::pow(best, 3), 32.0 * r2 / (n * beta * beta), 1e-4 * std::pow(best, 3));
            EXPECT_LT(error(best), error(best * 1.05));
            EXPECT_LT(error(best), error(best / 1.05));
        }
    EXPECT_TRUE(std::isinf(balancedRadiusSquared(0.01f, 10, 0)));
}

TEST(AdaptiveRadius, ShrinksByTheBalanceWithinTheSchedulesBounds) {
    const float alpha = 2.0f / 3.0f, r2 = 0.01f;
    const uint8_t flat = PhotonSpread::of(1024 * 10, 10);  // mean 1/2 exactly
    // A 3 x 3 image: the middle pixel reads its eight neighbours' moments too.
    AdaptiveRadius radius(3, 3);
    radius.add(4, 40, flat, r2);
    // Fewer than kWarmUpPhotons photons: alpha's schedule.
    EXPECT_FLOAT_EQ(radius.shrink(4, 100, 20, r2, alpha), (100 + alpha * 20) / 120);
    for (size_t i = 0; i < 9; ++i) radius.add(i, 40, flat, r2);
    // Flat: no bias to trade, the radius stays.
    EXPECT_FLOAT_EQ(radius.shrink(4, 100, 20, r2, alpha), 1.0f);
    // A strong Laplacian everywhere: as fast as alpha / 2's schedule, and no faster.
    AdaptiveRadius curved(3, 3);
    for (size_t i = 0; i < 9; ++i) curved.add(i, 40, 200, r2);
    EXPECT_FLOAT_EQ(curved.shrink(4, 100, 20, r2, alpha), (100 + alpha / 2 * 20) / 120);
    // In between: the balanced radius for the photon-weighted mean beta. Spreads 131/254 and
    // 127/254 (beta = 48 (s - 1/2) / r2: 75.6 and 0) in passes of 30 and 10 photons.
    AdaptiveRadius mild(3, 3);
    for (size_t i = 0; i < 9; ++i) {
        mild.add(i, 30, 131, r2);
        mild.add(i, 10, 127, r2);
    }
    const float beta = 0.75f * relativeLaplacian(131.0f / 254, r2);
    const float expected = balancedRadiusSquared(r2, 120, beta) / r2;
    ASSERT_GT(expected, (100 + alpha / 2 * 20) / 120);
    ASSERT_LT(expected, 1.0f);
    EXPECT_NEAR(mild.shrink(4, 100, 20, r2, alpha), expected, 1e-5f);
    // A corner pixel reads its three neighbours and itself.
    EXPECT_NEAR(mild.shrink(0, 100, 20, r2, alpha), expected, 1e-5f);

    // Saved and restored whole; a stream without the block starts anew.
    std::stringstream saved;
    mild.save(saved);
    AdaptiveRadius restored(3, 3);
    restored.restore(saved);
    EXPECT_FLOAT_EQ(restored.shrink(4, 100, 20, r2, alpha), expected);
    std::stringstream other("not the block");
    restored.restore(other);
    EXPECT_FLOAT_EQ(restored.shrink(4, 100, 20, r2, alpha), (100 + alpha * 20) / 120);
}

// SPPM with photons for direct light over a plane under a point light: the radii after
// `passes` passes over those after the first, at the pixels of the image's middle.
struct RadiusRun {
    std::vector<float> shrink;  // r2 now / r2 after pass 1
    Image image;
};
RadiusRun radiiUnderPointLight(float height, bool adaptive, int passes) {
    const int res = 32;
    SceneDescription d = test::pointLightPlane(0.5f, 10 * height * height, height, res, 2);
    d.render.direct = DirectLighting::Photons;
    d.render.photonsPerPass = 50000;
    d.render.adaptivePhotons = false;
    d.render.adaptiveRadius = adaptive;
    auto scene = Scene::build(std::move(d));
    SppmIntegrator sppm(scene);
    CancelToken cancel;
    EXPECT_TRUE(sppm.renderPass(cancel));
    std::vector<float> first;
    for (int y = 12; y < 20; ++y)
        for (int x = 12; x < 20; ++x) first.push_back(sppm.pixel(x, y).r2);
    for (int p = 1; p < passes; ++p) EXPECT_TRUE(sppm.renderPass(cancel));
    RadiusRun run;
    size_t k = 0;
    for (int y = 12; y < 20; ++y)
        for (int x = 12; x < 20; ++x) run.shrink.push_back(sppm.pixel(x, y).r2 / first[k++]);
    run.image = sppm.snapshot();
    return run;
}

float median(std::vector<float> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

// Under a light 1,000 units up the plane's radiance is flat to 1e-6 over the view: the
// radii keep their size, where alpha's schedule takes them down to 0.30 of theirs in 32
// passes (prod (k + alpha) / (k + 1) over the passes' photon counts).
TEST(AdaptiveRadius, RadiiKeepTheirSizeWhereTheLightIsFlat) {
    const RadiusRun fixed = radiiUnderPointLight(1000, false, 32), adaptive = radiiUnderPointLight(1000, true, 32);
    EXPECT_LT(median(fixed.shrink), 0.45f);
    EXPECT_GT(median(adaptive.shrink), 0.9f);
    // The same radiance, 5 / pi * 0.5 / pi ... = rho / pi * I / h^2 = 0.5 / pi * 10.
    const float expected = 0.5f / kPi * 10;
    EXPECT_NEAR(test::meanOver(adaptive.image, 12, 12, 20, 20).y, expected, 0.01f * expected);
    EXPECT_NEAR(test::meanOver(fixed.image, 12, 12, 20, 20).y, expected, 0.01f * expected);
}

// A light 0.1 above the plane makes a hot spot whose radiance, h^3 / (h^2 + x^2)^(3/2) times
// its peak, falls to half within 0.077 (a pixel is 0.087 wide): the discs' photons crowd
// toward their centres, the radii there shrink faster than alpha's schedule would take
// them, and the spot's estimate is less blurred (closer to its analytic value) than the
// schedule's.
TEST(AdaptiveRadius, RadiiShrinkFasterWhereTheLightCurves) {
    const float h = 0.1f;
    const RadiusRun fixed = radiiUnderPointLight(h, false, 32), adaptive = radiiUnderPointLight(h, true, 32);
    EXPECT_LT(median(adaptive.shrink), 0.8f * median(fixed.shrink));
    // The four pixels around the spot, each the mean of 16 x 16 points of it on the plane.
    const Camera camera(test::pointLightPlane(0.5f, 10 * h * h, h, 32, 2).camera);
    double truth = 0;
    const int n = 16;
    for (int y = 15; y < 17; ++y)
        for (int x = 15; x < 17; ++x)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const Ray ray = camera.generateRay(x + (i + 0.5f) / n, y + (j + 0.5f) / n, {0.5f, 0.5f});
                    const Vec3 p = ray.o + ray.d * (-ray.o.y / ray.d.y);
                    const double d2 = p.x * p.x + p.z * p.z + h * h;
                    truth += 0.5 / kPi * 10 * h * h * (h / std::sqrt(d2)) / d2 / (4.0 * n * n);
                }
    const double fixedSpot = test::meanOver(fixed.image, 15, 15, 17, 17).y;
    const double adaptiveSpot = test::meanOver(adaptive.image, 15, 15, 17, 17).y;
    EXPECT_LT(std::abs(adaptiveSpot - truth), 0.8 * std::abs(fixedSpot - truth))
        << "fixed " << fixedSpot << ", adaptive " << adaptiveSpot << ", analytic " << truth;
}

}  // namespace
}  // namespace photon
