// Light samples of a triangle-mesh light are drawn only from what of it lies above the
// receiving surface's plane (engine/math/clipped_triangle.h, engine/lights/area_light.cpp):
// a quad light standing on a surface's horizon no longer wastes the samples that fall behind
// it. Held to an independent quadrature of the irradiance, to the density a ray that finds
// the light is given, and to the variance of uniform area sampling over the whole quad.
#include <gtest/gtest.h>
#include <cmath>
#include "math/clipped_triangle.h"
#include "math/rng.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

TEST(AreaLightHorizon, AClippedTriangleKeepsThePartAboveThePlane) {
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    // x > 1 keeps the corner (1, 0), (2, 0), (1, 1): area 1/2.
    const ClippedTriangle corner = clipTriangleAbove(a, b, c, Vec3(1, 0, 0), Vec3(1, 0, 0));
    EXPECT_EQ(corner.corners, 3);
    EXPECT_NEAR(corner.area, 0.5f, 1e-6f);
    // x < 1 keeps the quad (0, 0), (1, 0), (1, 1), (0, 2): area 3/2, centroid (4/9, 7/9).
    const ClippedTriangle rest = clipTriangleAbove(a, b, c, Vec3(1, 0, 0), Vec3(-1, 0, 0));
    EXPECT_EQ(rest.corners, 4);
    EXPECT_NEAR(rest.area, 1.5f, 1e-6f);
    // Wholly above and wholly below.
    EXPECT_NEAR(clipTriangleAbove(a, b, c, Vec3(0, 0, -1), Vec3(0, 0, 1)).area, 2.0f, 1e-6f);
    EXPECT_EQ(clipTriangleAbove(a, b, c, Vec3(0, 0, 1), Vec3(0, 0, 1)).corners, 0);

    // Points from pointAt are on the kept side and uniform: their mean is the centroid.
    Rng rng(3, 0, 0, StreamPurpose::Test);
    const int n = 200000;
    double x = 0, y = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3 q = rest.pointAt({rng.uniform(), rng.uniform()});
        ASSERT_LE(q.x, 1.0f + 1e-6f);
        ASSERT_GE(q.x, 0.0f);
        ASSERT_LE(q.x + q.y, 2.0f + 1e-5f);
        x += q.x, y += q.y;
    }
    EXPECT_NEAR(x / n, 4.0 / 9.0, 0.003);
    EXPECT_NEAR(y / n, 7.0 / 9.0, 0.003);
}

constexpr double kLe = 2.0;

// A vertical light at x = 0.5 facing -x, from y = -0.5 to 0.5 and z = -0.5 to 0.5: seen from
// the floor y = 0 around the origin, its lower half is below the horizon. As one quad, or
// as a mesh of 4 x 4 quads (picked among by their bounds with the spatial sampler).
ShapeDescription wall(int cells) {
    ShapeDescription s = test::quad({0.5f, -0.5f, -0.5f}, {0, 0, 1}, {0, 1, 0}, 0, Color(float(kLe)));
    if (cells == 1) return s;
    s.mesh = {};
    const float size = 1.0f / float(cells);
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const uint32_t base = uint32_t(s.mesh.positions.size());
            const Vec3 o(0.5f, -0.5f + size * float(j), -0.5f + size * float(i));
            for (Vec3 v : {o, o + Vec3(0, 0, size), o + Vec3(0, size, size), o + Vec3(0, size, 0)})
                s.mesh.positions.push_back(v);
            for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) s.mesh.indices.push_back(base + k);
        }
    return s;
}

// The irradiance at p (normal n) from the wall, by the midpoint rule on a 600 x 600 grid.
double quadratureIrradiance(Vec3 p, Vec3 n) {
    const int k = 600;
    const double dA = 1.0 / (double(k) * k);
    double sum = 0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            const Vec3 y(0.5f, -0.5f + (float(j) + 0.5f) / k, -0.5f + (float(i) + 0.5f) / k);
            const Vec3 d = y - p;
            const double d2 = lengthSquared(d);
            const Vec3 w = d / std::sqrt(float(d2));
            sum += kLe * std::max(0.0f, dot(w, n)) * std::max(0.0f, w.x) / d2 * dA;
        }
    return sum;
}

// Uniform by area over the whole wall, computed here: what light samples were before.
double wholeWallVariance(Vec3 p, Vec3 n, int samples) {
    Rng rng(11, 0, 0, StreamPurpose::Test);
    double sum = 0, squares = 0;
    for (int k = 0; k < samples; ++k) {
        const Vec3 y(0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f);
        const Vec3 d = y - p;
        const float d2 = lengthSquared(d);
        const Vec3 w = d / std::sqrt(d2);
        const double value = kLe * std::max(0.0f, dot(w, n)) * std::max(0.0f, w.x) / d2;
        sum += value, squares += value * value;
    }
    const double mean = sum / samples;
    return squares / samples - mean * mean;
}

TEST(AreaLightHorizon, LightSamplesComeFromAboveTheReceiversPlane) {
    for (int cells : {1, 4}) {
        auto scene = Scene::build(test::lightOnly(wall(cells)));
        const std::pair<Vec3, Vec3> receivers[] = {
            {Vec3(0, 0, 0), Vec3(0, 1, 0)},                         // the light's lower half behind
            {Vec3(0.1f, 0.05f, 0.2f), normalize(Vec3(0.4f, 1, 0.2f))},  // tilted toward it: a slanted cut
            {Vec3(0, -0.2f, -0.1f), normalize(Vec3(-0.3f, 1, 0))},      // tilted away: a sliver above
        };
        for (const auto& [p, n] : receivers) {
            SCOPED_TRACE("cells " + std::to_string(cells) + ", point " + std::to_string(p.x) + " " +
                         std::to_string(p.y) + " " + std::to_string(p.z));
            const int samples = 40000;
            const double exact = quadratureIrradiance(p, n);
            const test::LightSampleEstimate e = test::irradianceFromLightSamples(*scene, p, n, samples, true);
            const double before = wholeWallVariance(p, n, samples);
            std::printf("%d cell(s): irradiance %.5f (quadrature %.5f); variance %.4g, %.3fx uniform area on the "
                        "whole wall; %d of %d samples brought nothing\n",
                        cells * cells, e.mean, exact, e.variance, e.variance / before, e.nothing, samples);
            EXPECT_NEAR(e.mean, exact, std::max(4 * std::sqrt(e.variance / samples), 1e-3 * exact));
            // No sample falls behind the receiver (a sliver of a triangle may round to none),
            // and no triangle wholly below it is picked: before the bounds' box was held to the
            // receiver's plane, half the picks from the origin went to the wall's lower half.
            EXPECT_LT(e.nothing, samples / 1000);
            // One quad: 0.16-0.31x the variance of sampling it whole by area when the part
            // above was sampled by area; by its solid angle warped by the receiver's cosine
            // (warped_light_pieces.h) 0.009-0.043x. Among 32 triangles the pick by bounds
            // decides more than the clipping does (0.11x from the origin, but 1.4x from the
            // point tilted away, where the bounds' cones are loose this close).
            if (cells == 1) EXPECT_LT(e.variance, 0.1 * before);
        }
    }
}

}  // namespace
}  // namespace photon
