// A mesh light of many triangles with the spatial light sampler: its light samples pick a
// triangle by a bound on the light it could bring to the point (engine/lights/area_light.cpp).
// The estimate is Lambert's irradiance, a ray that finds the light is given the density the
// sample was drawn with, triangles facing away are never picked, and the path tracer renders
// the image the power sampler (triangles by area) does, with less noise.
#include <gtest/gtest.h>
#include <cmath>
#include <photon/render.h>
#include "math/rng.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr int kTiles = 8;           // a grid of kTiles x kTiles square tiles
constexpr float kTileSize = 0.1f, kSpacing = 0.3f, kHeight = 0.6f;

// Tile (i, j)'s corners, counter-clockwise seen from below.
std::vector<Vec3> tileCorners(int i, int j) {
    const float x = (i - 0.5f * (kTiles - 1)) * kSpacing, z = (j - 0.5f * (kTiles - 1)) * kSpacing;
    const float h = 0.5f * kTileSize;
    return {{x - h, kHeight, z - h}, {x + h, kHeight, z - h}, {x + h, kHeight, z + h}, {x - h, kHeight, z + h}};
}
// Every third tile faces up, away from the floor below; the rest face down.
bool facesUp(int i, int j) { return (i + kTiles * j) % 3 == 0; }

// The tiles as one emissive mesh of 2 kTiles^2 triangles.
ShapeDescription tiles(Color emission) {
    ShapeDescription s = test::quad({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 0, emission);
    s.mesh = {};
    for (int j = 0; j < kTiles; ++j)
        for (int i = 0; i < kTiles; ++i) {
            const std::vector<Vec3> c = tileCorners(i, j);
            const uint32_t base = static_cast<uint32_t>(s.mesh.positions.size());
            for (Vec3 v : c) s.mesh.positions.push_back(v);
            // The face normal is (b - a) x (c - a): +y for the order 0, 3, 2; -y for 0, 1, 2.
            const std::vector<uint32_t> down = {0, 1, 2, 0, 2, 3}, up = {0, 3, 2, 0, 2, 1};
            for (uint32_t k : facesUp(i, j) ? up : down) s.mesh.indices.push_back(base + k);
        }
    return s;
}

TEST(MeshLightTriangles, SamplesByBoundsGiveLambertsIrradianceWithLessVariance) {
    const double le = 3.0;
    auto spatial = Scene::build(test::lightOnly(tiles(Color(float(le))), LightSamplerKind::Spatial));
    auto byArea = Scene::build(test::lightOnly(tiles(Color(float(le))), LightSamplerKind::Power));
    const Vec3 n(0, 1, 0);
    for (Vec3 p : {Vec3(0, 0, 0), Vec3(0.45f, 0.3f, -0.15f), Vec3(-1.0f, 0.5f, 0.9f)}) {
        SCOPED_TRACE("point " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z));
        double exact = 0;
        for (int j = 0; j < kTiles; ++j)
            for (int i = 0; i < kTiles; ++i)
                if (!facesUp(i, j)) exact += test::polygonIrradiance(p, n, tileCorners(i, j), le);
        const int samples = 40000;
        const test::LightSampleEstimate s = test::irradianceFromLightSamples(*spatial, p, n, samples, true);
        const test::LightSampleEstimate a = test::irradianceFromLightSamples(*byArea, p, n, samples, false);
        std::printf("irradiance %.5f (Lambert %.5f), by area %.5f; variance %.4g against %.4g by area (%.3fx); "
                    "no light found %d against %d\n",
                    s.mean, exact, a.mean, s.variance, a.variance, s.variance / a.variance, s.nothing, a.nothing);
        EXPECT_NEAR(s.mean, exact, 0.01 * exact);
        EXPECT_NEAR(a.mean, exact, 5 * std::sqrt(a.variance / samples));
        // A tile facing up is never picked from below it; by area a third of samples land there.
        EXPECT_EQ(s.nothing, 0);
        EXPECT_GT(a.nothing, samples / 4);
        EXPECT_LT(s.variance, 0.5 * a.variance);
    }
}

// The floor under the tiles, path-traced with direct light only: both ways of picking a
// triangle reach the same image (BSDF samples that find a tile weigh themselves against the
// light sample with the triangle's own probability), the spatial one with less noise.
SceneDescription floorUnderTiles(LightSamplerKind kind, uint64_t seed) {
    SceneDescription d = test::directLitFloor(kind, seed, 32);
    d.shapes.push_back(tiles(Color(3.0f)));
    return d;
}

TEST(MeshLightTriangles, SpatialAndByAreaRenderTheSameImageTheSpatialWithLessNoise) {
    const test::RendersBySampler r = test::renderBySampler(floorUnderTiles);
    const Image &spatial = r.spatial, &spatial2 = r.spatial2, &byArea = r.power, &byArea2 = r.power2;
    // Over the lit floor: the tiles facing up are seen from the camera, and the noise of
    // the pixels on their edges is the pixel's, not the light sample's.
    auto seesTile = [&](int x, int y) {
        for (int j = std::max(0, y - 1); j <= std::min(23, y + 1); ++j)
            for (int i = std::max(0, x - 1); i <= std::min(23, x + 1); ++i)
                for (const Image* image : {&spatial, &spatial2, &byArea, &byArea2})
                    if (maxComponent(image->at(i, j)) > 0.5f) return true;
        return false;
    };
    int floorPixels = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) floorPixels += !seesTile(x, y);
    ASSERT_GT(floorPixels, 100);
    auto noise = [&](const Image& a, const Image& b) {
        double d2 = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                if (!seesTile(x, y)) d2 += std::pow(average(a.at(x, y) - b.at(x, y)), 2);
        return std::sqrt(d2 / floorPixels);
    };
    test::expectSameBlockMeans(spatial, spatial2, byArea, byArea2, 8, 0.03f);
    const double ratio = noise(spatial, spatial2) / noise(byArea, byArea2);
    std::printf("noise over %d floor pixels, spatial against by area: %.3f\n", floorPixels, ratio);
    EXPECT_LT(ratio, 0.5);
}

}  // namespace
}  // namespace photon
