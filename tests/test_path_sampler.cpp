// Camera paths' random numbers (engine/math/path_sampler.h, engine/math/sobol.h): each draw
// an Owen-scrambled Sobol sequence over a pixel's passes. Held to the nets the sequence must
// form, to uniformity and independence of single samples, and, in SPPM's and the path
// tracer's renders, to the analytic radiance of a plane beside a square light and to less
// noise than independent numbers.
#include <gtest/gtest.h>
#include <bit>
#include <cmath>
#include <set>
#include <vector>
#include "camera/camera.h"
#include "materials/material.h"
#include "math/path_sampler.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

// Whether the points have exactly one in each elementary interval of area 1 / points.size()
// (a power of two, 2^m): for every split a + b = m, one point in each 2^a x 2^b cell.
bool isNet(const std::vector<Vec2>& points) {
    const int m = std::countr_zero(points.size());
    for (int a = 0; a <= m; ++a) {
        std::vector<int> counts(points.size(), 0);
        for (Vec2 p : points) {
            const size_t cx = static_cast<size_t>(p.x * float(1 << a)), cy = static_cast<size_t>(p.y * float(1 << (m - a)));
            if (++counts[cx << (m - a) | cy] > 1) return false;
        }
    }
    return true;
}

TEST(PathSampler, EachTwoDimensionalDrawIsANetInEveryAlignedBlock) {
    for (uint64_t key : {1ull, 0x9e3779b97f4a7c15ull, 12345678901234ull})
        for (uint32_t seed2 : {7u, 0xdeadbeefu})
            for (int m = 0; m <= 10; ++m)
                for (uint32_t block : {0u, 1u, 5u}) {
                    std::vector<Vec2> points;
                    for (uint32_t i = 0; i < (1u << m); ++i) points.push_back(sobol::sample2D(block << m | i, key, seed2));
                    EXPECT_TRUE(isNet(points)) << "key " << key << ", 2^" << m << " points, block " << block;
                }
}

TEST(PathSampler, EachOneDimensionalDrawIsStratified) {
    for (uint64_t key : {3ull, 0xfeedfacecafebeefull})
        for (int m = 0; m <= 12; ++m) {
            std::set<uint32_t> strata;
            for (uint32_t i = 0; i < (1u << m); ++i) strata.insert(uint32_t(sobol::sample1D(i, key) * float(1 << m)));
            EXPECT_EQ(strata.size(), size_t(1) << m) << "key " << key << ", 2^" << m << " samples";
        }
}

// Pass p of a path is sample p / 2 of its parity's sequence: a pixel's even passes, and its
// odd ones, each spread a draw over one stratum apiece.
TEST(PathSampler, APixelsEvenAndOddPassesAreEachANet) {
    Rng rng(1, 0, 0, StreamPurpose::Test);
    for (int parity : {0, 1}) {
        std::vector<Vec2> film, light;
        for (int64_t k = 0; k < 64; ++k) {
            PathSampler s(rng, 42, 2 * k + parity, 1234, 0);
            film.push_back(s.get2D());
            s.get2D(), s.get1D();
            light.push_back(s.get2D());
        }
        EXPECT_TRUE(isNet(film));
        EXPECT_TRUE(isNet(light));
    }
}

// A single sample, over pixels, is uniform, and the draws of a path (and a pixel's even and
// odd passes) are uncorrelated.
TEST(PathSampler, SingleSamplesAreUniformAndDrawsUncorrelated) {
    Rng rng(1, 0, 0, StreamPurpose::Test);
    const int pixels = 40000;
    std::vector<int> bins(16, 0);
    double mean = 0, sumXY = 0, sumOddEven = 0;
    for (int i = 0; i < pixels; ++i) {
        PathSampler even(rng, 9, 6, uint64_t(i), 0), odd(rng, 9, 7, uint64_t(i), 0);
        const float a = even.get1D();
        const Vec2 b = even.get2D();
        const float c = odd.get1D();
        ++bins[size_t(a * 16)];
        mean += a;
        sumXY += (a - 0.5) * (b.x - 0.5);
        sumOddEven += (a - 0.5) * (c - 0.5);
    }
    // The mean's standard deviation is sqrt(1/12 / n) = 0.0014; a product's is 1/12 / sqrt(n) = 0.0004.
    EXPECT_NEAR(mean / pixels, 0.5, 0.006);
    EXPECT_NEAR(sumXY / pixels, 0.0, 0.0017);
    EXPECT_NEAR(sumOddEven / pixels, 0.0, 0.0017);
    // Each of 16 bins holds n / 16 = 2500 +- 48 (one standard deviation).
    for (int count : bins) EXPECT_NEAR(count, pixels / 16, 250);
}

TEST(PathSampler, IndependentDrawsAreTheRngsNumbersInOrder) {
    Rng a(5, 3, 17, StreamPurpose::Camera), b(5, 3, 17, StreamPurpose::Camera);
    PathSampler s(a);
    for (int k = 0; k < 40; ++k) {
        const Vec2 u = s.get2D();
        EXPECT_EQ(u.x, b.uniform());
        EXPECT_EQ(u.y, b.uniform());
        EXPECT_EQ(s.get1D(), b.uniform());
    }
}

// A diffuse plane of albedo rho beside a square light of radiance Le at height 1, lit by
// light samples alone (the light's own material black, so nothing else brings light). The
// camera, 3 above the plane, sees no more than x = +-0.93 at the light's height, so the light
// (x from 1 to 2) hides none of the plane.
constexpr float kRho = 0.5f, kLe = 4.0f;
constexpr int kResolution = 32;
const std::vector<Vec3> kLightCorners{{1, 1, -0.5f}, {2, 1, -0.5f}, {2, 1, 0.5f}, {1, 1, 0.5f}};

SceneDescription squareLightPlane(SamplerKind sampler, uint64_t seed, int passes,
                                  IntegratorKind integrator = IntegratorKind::Sppm) {
    SceneDescription d = test::pointLightPlane(kRho, 0, 1, kResolution, 20);
    d.render.integrator = integrator;
    d.lights.clear();
    d.materials.push_back(makeDiffuse(Color(0.0f)));
    d.materialNames.push_back("light");
    // u x v = (+x) x (+z) points down, toward the plane.
    d.shapes.push_back(test::quad(kLightCorners[0], {1, 0, 0}, {0, 0, 1}, 1, Color(kLe)));
    d.render.sampler = sampler;
    d.render.seed = seed;
    d.render.passes = passes;
    d.render.photonsPerPass = 1000;
    d.render.adaptivePhotons = false;
    d.render.adaptiveCameraPaths = false;
    return d;
}

// The pixel's analytic value: rho / pi times the irradiance (Lambert's polygon formula),
// averaged over the pixel's area on the plane.
std::vector<double> analyticImage() {
    const Camera camera(squareLightPlane(SamplerKind::Sobol, 1, 1).camera);
    std::vector<double> image;
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) {
            double sum = 0;
            const int n = 6;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const Ray ray = camera.generateRay(x + (i + 0.5f) / n, y + (j + 0.5f) / n, {0.5f, 0.5f});
                    const Vec3 p = ray.o + ray.d * (-ray.o.y / ray.d.y);
                    sum += kRho / kPi * test::polygonIrradiance(p, {0, 1, 0}, kLightCorners, kLe);
                }
            image.push_back(sum / (n * n));
        }
    return image;
}

struct ErrorOverSeeds {
    double bias = 0;  // of the mean over seeds and pixels, relative to the analytic mean
    double rms = 0;   // of a render's pixels against their analytic values, over the analytic mean
};

ErrorOverSeeds errorOverSeeds(SamplerKind sampler, int passes, const std::vector<double>& analytic,
                              IntegratorKind integrator = IntegratorKind::Sppm) {
    double sum = 0, analyticSum = 0, squares = 0;
    const int seeds = 4;
    for (uint64_t seed = 1; seed <= seeds; ++seed) {
        const Image image = test::renderImage(squareLightPlane(sampler, seed, passes, integrator));
        for (int y = 0; y < kResolution; ++y)
            for (int x = 0; x < kResolution; ++x) {
                const double got = luminance(image.at(x, y)), want = analytic[size_t(y) * kResolution + x];
                sum += got, analyticSum += want, squares += (got - want) * (got - want);
            }
    }
    const double pixels = double(seeds) * kResolution * kResolution;
    return {sum / analyticSum - 1, std::sqrt(squares / pixels) / (analyticSum / pixels)};
}

TEST(PathSampler, SppmWithSobolPassesReachesTheAnalyticRadianceWithLessNoise) {
    const std::vector<double> analytic = analyticImage();
    const ErrorOverSeeds sobol = errorOverSeeds(SamplerKind::Sobol, 32, analytic);
    const ErrorOverSeeds independent = errorOverSeeds(SamplerKind::Independent, 32, analytic);
    // The mean over 4 x 1024 pixels: with independent numbers a pixel's error is 0.12 of the
    // mean, so the mean's is 0.002 (measured -0.0032); with Sobol passes 0.00015.
    EXPECT_NEAR(sobol.bias, 0.0, 0.003);
    EXPECT_NEAR(independent.bias, 0.0, 0.008);
    // Measured: 0.026 (Sobol) against 0.122 (independent), 4.7 times less error.
    EXPECT_LT(sobol.rms, 0.35 * independent.rms) << "Sobol " << sobol.rms << ", independent " << independent.rms;
}

TEST(PathSampler, PathTracerWithSobolSamplesReachesTheAnalyticRadianceWithLessNoise) {
    const std::vector<double> analytic = analyticImage();
    const ErrorOverSeeds sobol = errorOverSeeds(SamplerKind::Sobol, 32, analytic, IntegratorKind::Path);
    const ErrorOverSeeds independent = errorOverSeeds(SamplerKind::Independent, 32, analytic, IntegratorKind::Path);
    // Measured with light samples uniform by area on the square: means within 0.0002 and
    // 0.0006, error 0.029 against 0.117 of the mean. Drawn by solid angle warped by the
    // plane's cosine (warped_light_pieces.h) the light samples leave less to stratify:
    // 0.0101 against 0.0214.
    EXPECT_NEAR(sobol.bias, 0.0, 0.003);
    EXPECT_NEAR(independent.bias, 0.0, 0.008);
    EXPECT_LT(sobol.rms, 0.6 * independent.rms) << "Sobol " << sobol.rms << ", independent " << independent.rms;
}

}  // namespace
}  // namespace photon
