// render.disc_coverage (integrators/sppm/disc_coverage.h): the share of a gather disc that
// photons can land on, measured by rays, and SPPM's estimate divided by it.
#include <gtest/gtest.h>
#include <cstdio>
#include <cmath>
#include "integrators/sppm/disc_coverage.h"
#include "materials/material.h"
#include "camera/camera.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

// The share of the unit disc about (-d, 0) on the side x <= 0 of a straight edge at x = 0
// (the circular segment past the edge, acos d - d sqrt(1 - d^2), left out), and the mean of
// s = |x|^2 over that part, summed on a fine grid.
struct Expected {
    double share, meanSpread;
};
Expected halfPlane(double d) {
    const int n = 2000;
    double inside = 0, all = 0, spread = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = -1 + (i + 0.5) * 2.0 / n, y = -1 + (j + 0.5) * 2.0 / n, s = x * x + y * y;
            if (s > 1) continue;
            ++all;
            if (x - d > 0) continue;
            ++inside;
            spread += s;
        }
    const double segment = std::acos(d) - d * std::sqrt(1 - d * d);
    EXPECT_NEAR(inside / all, 1 - segment / kPi, 1e-3);  // the grid against the formula
    return {1 - segment / kPi, spread / inside};
}

// The measured share and spread about p, the disc of radius 1 on the floor (normal +y),
// averaged over `turns` evenly spaced turns of the spiral.
DiscCoverage meanCoverage(const Scene& scene, Vec3 p, KernelKind kernel = KernelKind::Uniform, int turns = 512) {
    double share = 0, spread = 0;
    for (int i = 0; i < turns; ++i) {
        const DiscCoverage c = measureDiscCoverage(scene, p, {0, 1, 0}, 1.0f, false, kernel, (i + 0.5f) / turns);
        share += c.share;
        spread += c.meanSpread;
    }
    return {static_cast<float>(share / turns), static_cast<float>(spread / turns)};
}

// A floor for x <= 0 (z within +-3) and, with `wall`, a wall along its edge facing it.
std::shared_ptr<const Scene> floorToAnEdge(bool wall) {
    SceneDescription d = test::hitTestScene();
    d.shapes = {test::quad({-3, 0, 3}, {3, 0, 0}, {0, 0, -6}, 0)};  // facing +y
    if (wall) d.shapes.push_back(test::quad({0, 0, -3}, {0, 0, 6}, {0, 2, 0}, 0));  // facing -x
    return Scene::build(std::move(d));
}

TEST(DiscCoverage, AStraightEdgeLeavesOutItsSegment) {
    for (bool wall : {false, true}) {
        auto scene = floorToAnEdge(wall);
        for (double d : {0.0, 0.3, 0.6, 0.9}) {
            const Expected e = halfPlane(d);
            const DiscCoverage c = meanCoverage(*scene, {static_cast<float>(-d), 0, 0});
            EXPECT_NEAR(c.share, e.share, 0.003) << "d " << d << (wall ? " by a wall" : " at a cliff");
            EXPECT_NEAR(c.meanSpread, e.meanSpread, 0.002) << "d " << d;
        }
        // A disc the edge does not reach is whole, every turn.
        const DiscCoverage whole = measureDiscCoverage(*scene, {-1.5f, 0, 0}, {0, 1, 0}, 1.0f, false, KernelKind::Uniform, 0.3f);
        EXPECT_EQ(whole.share, 1.0f);
        EXPECT_NEAR(whole.meanSpread, 0.5f, 1e-6f);
    }
}

// The biweight kernel weighs the centre more: a cut at the rim takes less of it.
TEST(DiscCoverage, TheKernelWeighsTheShare) {
    auto scene = floorToAnEdge(true);
    const double d = 0.6;
    // The biweight's share of the part past the edge: 3 (1 - s)^2 over the segment, by grid.
    const int n = 2000;
    double past = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = -1 + (i + 0.5) * 2.0 / n, y = -1 + (j + 0.5) * 2.0 / n, s = x * x + y * y;
            if (s <= 1 && x > d) past += 3 * (1 - s) * (1 - s) * (4.0 / (n * n));
        }
    const DiscCoverage c = meanCoverage(*scene, {static_cast<float>(-d), 0, 0}, KernelKind::Biweight);
    EXPECT_NEAR(c.share, 1 - past / kPi, 0.003);
    EXPECT_GT(c.share, halfPlane(d).share + 0.02);
}

// A box standing on the floor: no photon comes under it, though a column there finds the
// floor (or the box's bottom face, which a two-sided material turns up); its side cuts the
// way to it. A pane of glass over the floor receives no photons and hides none, nor does a
// block of rough glass standing on it: photons reach the floor through both.
TEST(DiscCoverage, ABoxOnTheFloorCutsTheDiscAndGlassDoesNot) {
    SceneDescription d = test::hitTestScene();
    d.materials.push_back(makeDielectric(1.5f));
    d.materials.push_back(makeRoughDielectric(1.5f, 0.3f));
    d.materialNames.push_back("glass");
    d.materialNames.push_back("rough glass");
    const uint32_t glass = static_cast<uint32_t>(d.materials.size() - 2), rough = glass + 1;
    d.shapes = {test::quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0)};
    for (const ShapeDescription& face : test::boxFaces({0.3f, 0, -2}, {1.3f, 2, 2}, 0)) d.shapes.push_back(face);
    d.shapes.push_back(test::quad({-3, 0.5f, 3}, {2.5f, 0, 0}, {0, 0, -6}, glass));  // over x < -0.5
    for (const ShapeDescription& face : test::boxFaces({-2.6f, 0, -0.2f}, {-2.2f, 2, 0.2f}, rough))
        d.shapes.push_back(face);
    auto scene = Scene::build(std::move(d));
    EXPECT_NEAR(meanCoverage(*scene, {0, 0, 0}).share, halfPlane(0.3).share, 0.003);
    EXPECT_EQ(measureDiscCoverage(*scene, {-1.8f, 0, 0}, {0, 1, 0}, 1.0f, false, KernelKind::Uniform, 0.7f).share, 1.0f);
}

// A post thinner than the disc standing on the floor beside its centre: no photon comes
// under it, but the floor behind it is lit from above and gathered like the rest, so only
// its footprint is cut (the way to a column's foot behind it goes into the post and out
// again). Measured 0.9866 and, with two posts in a row, 0.9901 (the spiral's fixed rings
// against the footprints' 0.9873); counting the floor behind them as cut too, as a box's
// side cuts it, read 0.9064 and 0.8617: the estimate there 9% and 15% high.
TEST(DiscCoverage, APostCutsOnlyItsFootprint) {
    SceneDescription d = test::hitTestScene();
    d.shapes = {test::quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0)};
    for (const ShapeDescription& face : test::boxFaces({0.3f, 0, -0.1f}, {0.5f, 2, 0.1f}, 0)) d.shapes.push_back(face);
    auto scene = Scene::build(std::move(d));
    EXPECT_NEAR(meanCoverage(*scene, {0, 0, 0}).share, 1 - 0.2 * 0.2 / kPi, 0.003);
    // Two posts in a row, the second behind the first: four crossings, still the footprints.
    SceneDescription two = test::hitTestScene();
    two.shapes = {test::quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0)};
    for (float x0 : {0.2f, 0.5f})
        for (const ShapeDescription& face : test::boxFaces({x0, 0, -0.1f}, {x0 + 0.1f, 2, 0.1f}, 0)) two.shapes.push_back(face);
    auto rows = Scene::build(std::move(two));
    // The spiral's sixteen rings stay where they are as it turns: a footprint thinner than
    // the gap between two rings reads a few thousandths off.
    EXPECT_NEAR(meanCoverage(*rows, {0, 0, 0}).share, 1 - 2 * 0.1 * 0.2 / kPi, 0.005);
}

// The floor scenes below, seen from above (32 x 32, 0.0875 units a pixel), rendered by
// photons alone (`bounces` of them) with a fixed radius of 0.2: alpha near 1, radii not
// following the light.
SceneDescription floorUnderAFarLight(Vec3 light, int bounces) {
    SceneDescription d = test::pointLightPlane(0.5f, 4e6f, 1000, 32, 3);
    d.lights[0].position = light;
    d.render.direct = DirectLighting::Photons;
    d.render.maxDepth = bounces;
    d.render.passes = 32;
    d.render.photonsPerPass = 100000;
    d.render.adaptivePhotons = false;
    d.render.adaptiveRadius = false;
    d.render.initialRadius = 0.2f;
    d.render.alpha = 0.9999f;
    return d;
}

// A floor lit by a far point light, up to a wall it meets at x = 0. The light stands off to
// the floor's side, so the wall is lit too and its photons show the corner to the discs
// beside it.
Image cornerRender(bool coverage, int passes, int threads = 0) {
    SceneDescription d = floorUnderAFarLight({-200, 1000, 0}, 1);
    d.render.passes = passes;
    d.shapes = {test::quad({-3, 0, 3}, {3, 0, 0}, {0, 0, -6}, 0), test::quad({0, 0, -3}, {0, 0, 6}, {0, 2, 0}, 0)};
    d.render.discCoverage = coverage;
    return threads > 0 ? test::renderWithThreads(std::move(d), threads) : test::renderImage(std::move(d));
}

// The column of pixels along the wall (x from -0.0875 to 0) against rho / pi E, E the far
// light's irradiance, after 128 passes: with the coverage within 3% (over 12 seeds 0.994 of
// it, standard deviation 0.008 a seed); without, low by the share the wall cuts off, about
// a third (0.640). Three columns further, where the discs are whole, both within 1.5%
// (0.997, deviation 0.004). The coverage is measured only in passes whose photons show
// the wall inside a disc's sphere: with half the photons a pass (50,000) a disc by the
// wall misses them in about one pass in five and the column reads 0.95 (docs/sppm.md).
TEST(DiscCoverage, TheFloorAlongAWallMatchesItsIrradiance) {
    const Image covered = cornerRender(true, 128), plain = cornerRender(false, 128);
    const Vec3 light{-200, 1000, 0};
    const Camera camera(test::pointLightPlane(0.5f, 4e6f, 1000, 32, 3).camera);
    for (int x : {15, 12}) {
        double expected = 0;
        for (int y = 4; y < 28; ++y) {
            const Vec3 p = test::planePointSeen(camera, x + 0.5f, y + 0.5f);
            const Vec3 toLight = light - p;
            const double dist2 = dot(toLight, toLight);
            expected += 0.5 / kPi * 4e6 * (toLight.y / std::sqrt(dist2)) / dist2 / 24;
        }
        const double withCoverage = test::meanOver(covered, x, 4, x + 1, 28).y;
        const double whole = test::meanOver(plain, x, 4, x + 1, 28).y;
        std::printf("  column %d: %.4f with the coverage, %.4f without, of %.4f\n", x, withCoverage / expected,
                    whole / expected, expected);
        EXPECT_NEAR(withCoverage, expected, (x == 15 ? 0.03 : 0.015) * expected) << "column " << x;
        if (x == 15) EXPECT_LT(whole, 0.75 * expected);
        else EXPECT_NEAR(whole, expected, 0.015 * expected);
    }
}

// The floor of the scene above beside two black posts 0.05 square (x from 0.02 to 0.07
// and, mirrored about x = -0.4375, from -0.945 to -0.895; z within 0.025; two units tall),
// lit from straight above: each one's shadow is its footprint. Two bounces, so that
// photons the floor sends up land on the posts' sides and mark the discs around them for
// measuring; the black posts send none back, so the floor's light is the far light's alone.
// The pixels beside each post on the camera's side of it (x from -0.175 to 0, and from
// -0.875 to -0.7; z within 0.175), whose discs of radius 0.2 reach past the post, against
// rho / pi E. Over 12 seeds with one post (512 passes of 50,000 photons) they read 0.9965
// of it, standard deviation 0.0049 a seed (the measured shares of discs, drawn anew each
// pass, more than the photons); counting the floor behind the post as cut read them
// 1.0183 (deviation 0.0054). With the two posts' 16 pixels, 0.9970 (deviation 0.0042) and
// 1.0187 (0.0043): 1.4% holds the first by 2.6 deviations and fails the second in six
// seeds of seven.
TEST(DiscCoverage, TheFloorBesideAThinPostMatchesItsIrradiance) {
    const Vec3 light{0, 1000, 0};
    SceneDescription d = floorUnderAFarLight(light, 2);
    d.render.passes = 512;
    d.render.photonsPerPass = 50000;
    d.materials.push_back(makeDiffuse(Color(0.0f)));
    d.materialNames.push_back("black");
    d.shapes = {test::quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0)};
    for (float x0 : {0.02f, -0.945f})
        for (const ShapeDescription& face : test::boxFaces({x0, 0, -0.025f}, {x0 + 0.05f, 2, 0.025f}, 1))
            d.shapes.push_back(face);
    const Camera camera(d.camera);
    const Image image = test::renderImage(std::move(d));
    double expected = 0, seen = 0;
    for (int y = 14; y < 18; ++y)
        for (int x : {6, 7, 14, 15}) {
            const Vec3 p = test::planePointSeen(camera, x + 0.5f, y + 0.5f);
            EXPECT_TRUE(x > 10 ? p.x < 0.0f : p.x > -0.875f && p.x < -0.7f) << x;
            EXPECT_LT(std::abs(p.z), 0.175f);
            const Vec3 toLight = light - p;
            const double dist2 = dot(toLight, toLight);
            expected += 0.5 / kPi * 4e6 * (toLight.y / std::sqrt(dist2)) / dist2 / 16;
            seen += image.at(x, y).y / 16;
        }
    std::printf("  beside the posts: %.4f of %.4f\n", seen / expected, expected);
    EXPECT_NEAR(seen, expected, 0.014 * expected);
}

TEST(DiscCoverage, TheImageIsTheSameOnAnyThreadCount) {
    const Image one = cornerRender(true, 32, 1), two = cornerRender(true, 32, 2);
    ASSERT_EQ(one.rgb.size(), two.rgb.size());
    for (size_t i = 0; i < one.rgb.size(); ++i) ASSERT_EQ(one.rgb[i], two.rgb[i]) << "value " << i;
}

}  // namespace
}  // namespace photon
