// Light samples on mesh lights that follow what each part brings to the receiver
// (engine/lights/warped_light_pieces.h): by solid angle warped by its cosine close by, by
// area through the corners' geometric term farther away. The inverse of the spherical
// triangle's map, the bilinear density, Lambert's irradiance with less variance than
// samples uniform by area, and the density a ray that finds the light is given.
#include <gtest/gtest.h>
#include <cmath>
#include "lights/warped_light_pieces.h"
#include "math/bilinear_density.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "math/spherical_triangle.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

TEST(WarpedLightPieces, TheSphericalTrianglesMapIsInvertedToItsNumbers) {
    Rng rng(5, 0, 0, StreamPurpose::Test);
    const Vec3 p(0.1f, -0.3f, 0.2f);
    const Vec3 triangles[][3] = {{{0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}},
                                 {{-1, 1, -1}, {1, 1, -1}, {0, 1, 2}},
                                 {{0.3f, 0.01f, 0}, {2, 0.02f, 0.5f}, {1, 0.3f, 3}}};
    float worst = 0;
    for (const auto& t : triangles)
        for (int i = 0; i < 20000; ++i) {
            const Vec2 u{rng.uniform(), rng.uniform()};
            const std::optional<Vec3> w = sampleSphericalTriangle(p, t[0], t[1], t[2], u);
            ASSERT_TRUE(w);
            const std::optional<Vec2> back = invertSphericalTriangleSample(p, t[0], t[1], t[2], *w);
            ASSERT_TRUE(back);
            worst = std::max({worst, std::abs(back->x - u.x), std::abs(back->y - u.y)});
            if (std::abs(back->x - u.x) > 1e-3f || std::abs(back->y - u.y) > 1e-3f) {
                ADD_FAILURE() << "u " << u.x << " " << u.y << " back " << back->x << " " << back->y;
                return;
            }
        }
    std::printf("largest difference %.3g\n", worst);
}

TEST(WarpedLightPieces, BilinearSamplesFollowTheirDensity) {
    // E[g(u) / density(u)] is the integral of g over the square, 1 + 1/2 + 1/3 here.
    const double exact = 1.0 + 0.5 + 1.0 / 3.0;
    for (const BilinearCorners& c : {BilinearCorners{{1, 1, 1, 1}}, BilinearCorners{{0.01f, 1, 3, 0.2f}},
                                     BilinearCorners{{0, 0, 1, 0.5f}}, BilinearCorners{{2, 0.01f, 0.01f, 0.01f}}}) {
        Rng rng(8, 0, 0, StreamPurpose::Test);
        const int n = 200000;
        double sum = 0, squares = 0;
        for (int i = 0; i < n; ++i) {
            const Vec2 u = sampleBilinear({rng.uniform(), rng.uniform()}, c);
            ASSERT_GE(u.x, 0.0f);
            ASSERT_LT(u.x, 1.0f);
            ASSERT_GE(u.y, 0.0f);
            ASSERT_LT(u.y, 1.0f);
            const double v = (1.0 + u.x + u.y * u.y) / c.density(u);
            sum += v, squares += v * v;
        }
        const double mean = sum / n, sigma = std::sqrt((squares / n - mean * mean) / n);
        EXPECT_NEAR(mean, exact, 4 * sigma + 1e-4) << c.w[0] << " " << c.w[1] << " " << c.w[2] << " " << c.w[3];
    }
}

constexpr float kLe = 2.0f;

// A 1 x 1 quad light at height 1 facing down, alone in the scene.
std::shared_ptr<const Scene> ceilingQuad() {
    return Scene::build(test::lightOnly(test::quad({-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, 0, Color(kLe))));
}
const std::vector<Vec3> kQuadCorners{{-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f}, {0.5f, 1, 0.5f}, {-0.5f, 1, 0.5f}};

// The variance of one light sample's irradiance estimate drawn uniformly by area on the quad.
double uniformAreaVariance(Vec3 p, Vec3 n, int samples) {
    Rng rng(12, 0, 0, StreamPurpose::Test);
    double sum = 0, squares = 0;
    for (int i = 0; i < samples; ++i) {
        const Vec3 y(rng.uniform() - 0.5f, 1, rng.uniform() - 0.5f), d = y - p;
        const double d2 = lengthSquared(d), w = 1.0 / std::sqrt(d2);
        const double v = kLe * std::max(0.0, dot(d, n) * w) * std::max(0.0, d.y * w) / d2;
        sum += v, squares += v * v;
    }
    const double mean = sum / samples;
    return squares / samples - mean * mean;
}

// Receivers wholly below the quad, tilted ones that still see all of it, and ones far to its
// side that see it at a grazing angle: Lambert's irradiance, the density a ray that finds the
// light gives, and how much less the estimate varies than with points uniform by area.
TEST(WarpedLightPieces, AQuadsIrradianceWithLessVarianceThanByArea) {
    auto scene = ceilingQuad();
    struct Receiver {
        Vec3 p, n;
        double atMost;  // of the variance by area
    };
    // Farther than WarpedLightPieces::kNear radii and wholly above the receiver's plane, the
    // quad is sampled uniformly by area (the last two): the same variance.
    const Receiver receivers[] = {
        {{0.1f, 0.7f, 0.2f}, {0, 1, 0}, 0.1},                       // under it, 30 cm
        {{0.2f, 0.98f, 0.1f}, {0, 1, 0}, 0.01},                     // under it, 2 cm
        {{2.0f, 0.9f, 0.0f}, normalize(Vec3(-1, 1, 0)), 0.01},      // beside it, tilted toward it
        {{0.0f, 0.5f, 0.0f}, normalize(Vec3(0.2f, 1, -0.3f)), 0.1},  // below it, tilted
        {{2.5f, 0.99f, 0.3f}, normalize(Vec3(-0.1f, 1, 0)), 0.2},   // to its side, grazing, one triangle near and one far
        {{0.3f, -2.0f, 0.0f}, {0, 1, 0}, 1.1},                      // 3 m below
        {{3.0f, 0.95f, 0.5f}, {0, 1, 0}, 1.1},                      // far to its side, grazing
    };
    for (const Receiver& r : receivers) {
        SCOPED_TRACE(testing::Message() << "receiver " << r.p.x << " " << r.p.y << " " << r.p.z);
        const int samples = 40000;
        const test::LightSampleEstimate e = test::irradianceFromLightSamples(*scene, r.p, r.n, samples, true);
        const double exact = test::polygonIrradiance(r.p, r.n, kQuadCorners, kLe);
        const double byArea = uniformAreaVariance(r.p, r.n, samples);
        std::printf("irradiance %.6g (Lambert %.6g); variance %.4g, %.4fx that by area\n", e.mean, exact, e.variance,
                    e.variance / byArea);
        EXPECT_NEAR(e.mean, exact, std::max(4 * std::sqrt(e.variance / samples), 1e-4 * exact));
        EXPECT_EQ(e.nothing, 0);
        EXPECT_LT(e.variance, r.atMost * byArea);
        // Unfitted (ReceiverSide::fitted, the path tracer's deeper vertices): by area but
        // within a piece's radius, unbiased all the same, with the density rays find.
        const test::LightSampleEstimate plain =
            test::irradianceFromLightSamples(*scene, r.p, ReceiverSide(r.n, true, false), samples, true);
        EXPECT_NEAR(plain.mean, exact, std::max(4 * std::sqrt(plain.variance / samples), 1e-4 * exact));
    }
}

// A point on the light itself (a light's own diffuse face, which paths bounce off) lies in
// its plane, where the solid angle's formula gives the whole hemisphere: it must get
// nothing from the light. It once did: the Cornell box's path tracer read 6.5% bright with
// its light lowered into view of its top.
TEST(WarpedLightPieces, APointOnTheLightGetsNothingFromIt) {
    auto scene = ceilingQuad();
    const Light& light = scene->lights().light(0);
    Rng rng(4, 0, 0, StreamPurpose::Test);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 p(rng.uniform() - 0.5f, 1, rng.uniform() - 0.5f);
        for (Vec3 n : {Vec3(0, -1, 0), Vec3(0, 1, 0), normalize(Vec3(0.3f, -1, 0.1f))}) {
            const std::optional<LightSample> ls = light.sampleIncident(p, n, {rng.uniform(), rng.uniform()});
            if (ls) EXPECT_EQ(ls->weight.x * std::max(0.0f, dot(ls->wi, n)), 0.0f) << p.x << " " << p.z;
        }
    }
}

// A point in a medium weighs no cosine: its samples are uniform in the solid angle of the
// part of the quad on its side, and their mean is Le times that solid angle.
TEST(WarpedLightPieces, APointInAMediumSamplesTheSolidAngleUniformly) {
    auto scene = ceilingQuad();
    const Light& light = scene->lights().light(0);
    const Vec3 p(0.2f, 0.6f, -0.1f);
    const double solidAngle = sphericalTriangleSolidAngle(p, kQuadCorners[0], kQuadCorners[1], kQuadCorners[2]) +
                              sphericalTriangleSolidAngle(p, kQuadCorners[0], kQuadCorners[2], kQuadCorners[3]);
    // The side facing the light sees all of it; the side tilted 60 degrees from it, part.
    for (Vec3 n : {Vec3(0, 1, 0), normalize(Vec3(1, 0.58f, 0))}) {
        Rng rng(6, 0, 0, StreamPurpose::Test);
        const int samples = 20000;
        double sum = 0;
        for (int i = 0; i < samples; ++i) {
            const std::optional<LightSample> ls = light.sampleIncident(p, ReceiverSide(n, false, false), {rng.uniform(), rng.uniform()});
            if (!ls || !(dot(ls->wi, n) > 0)) continue;
            sum += ls->weight.x;
            if (n.y == 1) EXPECT_NEAR(ls->pdf * solidAngle, 1.0, 1e-3);
            test::expectRayFindsLightSample(*scene, light, p, ReceiverSide(n, false, false), *ls, i);
        }
        if (n.y == 1) EXPECT_NEAR(sum / samples, kLe * solidAngle, 1e-3 * kLe * solidAngle);
        else EXPECT_LT(sum / samples, 0.8 * kLe * solidAngle);
    }
}

// So is the uniform sky: its samples in a medium are uniform over the side's hemisphere.
TEST(WarpedLightPieces, TheSkyInAMediumIsSampledUniformlyOverTheSide) {
    SceneDescription d = test::lightOnly(test::quad({-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, 0, Color(0.0f)));
    d.shapes.clear();
    LightDescription sky;
    sky.kind = LightDescription::Kind::Environment;
    sky.radiance = Color(0.7f);
    d.lights.push_back(sky);
    auto scene = Scene::build(d);
    const Light& light = scene->lights().light(0);
    const Vec3 n = normalize(Vec3(0.3f, 1, 0.2f));
    Rng rng(2, 0, 0, StreamPurpose::Test);
    for (int i = 0; i < 1000; ++i) {
        const std::optional<LightSample> ls = light.sampleIncident({0, 0, 0}, ReceiverSide(n, false, false), {rng.uniform(), rng.uniform()});
        ASSERT_TRUE(ls);
        EXPECT_GT(dot(ls->wi, n), 0.0f);
        EXPECT_NEAR(ls->pdf, 1.0f / (2 * kPi), 1e-6f);
        EXPECT_NEAR(ls->weight.x, 0.7f * 2 * kPi, 1e-4f);
        EXPECT_EQ(light.pdfIncident({0, 0, 0}, ReceiverSide(n, false, false), ls->wi), ls->pdf);
        EXPECT_EQ(light.pdfIncident({0, 0, 0}, ReceiverSide(n, false, false), -ls->wi), 0.0f);
    }
}

}  // namespace
}  // namespace photon
