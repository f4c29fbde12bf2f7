// pbrt-v4's procedural cloud (media/cloud_density.h): its height profile, its noise against
// the fractal sum of texture/perlin_noise.h, the grid it is sampled on against the cloud's
// own optical depth along rays, and the scene format's "cloud" density.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include "math/density_grid.h"
#include "math/rng.h"
#include "media/cloud_density.h"
#include "texture/perlin_noise.h"
#include "scene_loader_fixture.h"

namespace photon::cloud_density_tests {
namespace {

// At the bottom of its box the cloud is solid (the profile adds 2 (0.5 - y) >= 1 there),
// and at height 1 it is clear, whatever the noise.
TEST(CloudDensity, IsSolidAtTheFloorAndClearAtTheTop) {
    const CloudParameters cloud;
    Rng rng(2, 0, 0, StreamPurpose::Test);
    for (int k = 0; k < 1000; ++k) {
        const float x = rng.uniform(), z = rng.uniform();
        EXPECT_EQ(cloudDensity({x, -0.1f * rng.uniform(), z}, cloud), 1.0f);
        EXPECT_EQ(cloudDensity({x, 1.0f, z}, cloud), 0.0f);
    }
}

// Without wisps the density is (1 - y) 4.5 density times half the five-octave fractal sum at
// the cloud's frequency (pbrt-v4 starts the cloud's octaves at weight 1/2, its FBm at 1),
// clamped, between heights 0.5 and 1 where the profile adds nothing.
TEST(CloudDensity, WithoutWispsIsTheFractalSumOfTheNoise) {
    CloudParameters cloud;
    cloud.wispiness = 0;
    cloud.density = 0.7f;
    Rng rng(3, 0, 0, StreamPurpose::Test);
    int inBetween = 0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 p(rng.uniform(), 0.5f + 0.5f * rng.uniform(), rng.uniform());
        const float fbm = fractalBrownianMotion(p * cloud.frequency, 0.5f, 5);
        const float expected = std::clamp((1 - p.y) * 4.5f * cloud.density * 0.5f * fbm, 0.0f, 1.0f);
        EXPECT_NEAR(cloudDensity(p, cloud), expected, 1e-5f) << p.x << " " << p.y << " " << p.z;
        inBetween += expected > 0 && expected < 1;
    }
    EXPECT_GT(inBetween, 200);  // the comparison is not all clamps
}

// The grid the scene samples the cloud on, at the resolution chosen for its frequency, gives
// each ray's optical depth within 5% of the cloud's own (a midpoint rule of 20,000 steps), 2.5%
// in RMS and 1% on average: rays across the box at random, through the wispy middle heights
// (measured 1.7% RMS, 3.7% at worst; 64^3 samples gave 4.8% and 18%, 256^3 1.0% and 2.4%).
TEST(CloudDensity, TheSampledGridKeepsTheOpticalDepthOfRays) {
    const CloudParameters cloud;  // pbrt-v4's defaults: frequency 5, wispiness 1
    const int n = cloudResolution(cloud, 1.0f);
    EXPECT_EQ(n, 158);
    const DensityGrid grid(n, n, n, sampleCloud(cloud, {n, n, n}, Vec3(0.0f), Vec3(1.0f)),
                           DensityGrid::latticeFromBox(n, n, n, Vec3(0.0f), Vec3(1.0f)));
    Rng rng(4, 0, 0, StreamPurpose::Test);
    double worst = 0, sumSq = 0, sum = 0;
    constexpr int kRays = 24, kSteps = 20000;
    for (int r = 0; r < kRays; ++r) {
        // From the x = 0 face to the x = 1 face at heights 0.3 to 0.75.
        const Vec3 a(0.0f, 0.3f + 0.45f * rng.uniform(), rng.uniform());
        const Vec3 b(1.0f, 0.3f + 0.45f * rng.uniform(), rng.uniform());
        const Vec3 d = b - a;
        double exact = 0;
        for (int s = 0; s < kSteps; ++s) exact += cloudDensity(a + d * ((s + 0.5f) / kSteps), cloud);
        exact /= kSteps;
        const double sampled = grid.integral(a, d, 1.0f);
        const double error = (sampled - exact) / exact;
        worst = std::max(worst, std::abs(error));
        sumSq += error * error;
        sum += error;
        EXPECT_NEAR(sampled, exact, 0.05 * exact) << "ray " << r;
    }
    std::printf("  %d^3 samples: optical depth error mean %.4f, RMS %.4f, worst %.4f\n", n, sum / kRays,
                std::sqrt(sumSq / kRays), worst);
    EXPECT_LT(std::sqrt(sumSq / kRays), 0.025);
    EXPECT_LT(std::abs(sum / kRays), 0.01);
}

// {"cloud": {...}} in a medium's "density": sampled at the resolution its frequency asks for
// over its bounds, or at the one given.
TEST(CloudDensity, TheSceneFormatSamplesACloud) {
    Json doc = test::fullScene();
    doc["media"] = {{"sky", {{"scattering", {10, 10, 10}}, {"density", {{"cloud", {{"frequency", 2}}}, {"bounds", {{0, 0, 0}, {1, 2, 1}}}}}}}};
    const SceneDescription d = test::load(doc);
    const DensityGrid& grid = *d.media[0].density;
    EXPECT_EQ(grid.nx(), 64);  // 4 samples a period of 2 * 1.99^3 over 1
    EXPECT_EQ(grid.ny(), 127);
    CloudParameters two;
    two.frequency = 2;
    const float h = 2.0f / 127;  // cell height
    EXPECT_NEAR(grid.at({0.5f / 64, 0.5f * h, 0.5f / 64}), cloudDensity({0.5f / 64, 0.5f * h, 0.5f / 64}, two), 1e-6f);
    doc["media"]["sky"]["density"]["resolution"] = {4, 5, 6};
    const SceneDescription e = test::load(doc);
    EXPECT_EQ(e.media[0].density->nz(), 6);
    test::expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["sky"]["density"]["values"] = {1}; },
                      "media.sky.density", "give either \"cloud\" or \"values\", not both");
    test::expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["sky"]["density"]["cloud"]["frequency"] = 0; },
                      "media.sky.density.cloud.frequency", "must be > 0");
}

}  // namespace
}  // namespace photon::cloud_density_tests
