// Textures read at the hit point: the spherical, cylindrical and planar mappings, the solid
// checkerboard and pbrt-v4's noise textures, against their definitions; the point reaching
// them from the integrators (a cut-out and a bump), the scene JSON and the pbrt import.
#include <cmath>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "materials/normal_map.h"
#include "pbrt_import_fixture.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/perlin_noise.h"
#include "texture/textures.h"

namespace photon::test {
namespace {

// A texture whose colour is the (s, t) it is read at: bilinear between (0, 0, 0) at
// (0, 0), (1, 0, 0) at (1, 0), (0, 1, 0) at (0, 1) and (1, 1, 0) at (1, 1).
std::shared_ptr<const Texture> stProbe(TextureMapping mapping) {
    return makeBilerpTexture(Color(0.0f), Color(0, 1, 0), Color(1, 0, 0), Color(1, 1, 0), mapping);
}

Vec2 stAt(const Texture& probe, Vec3 p) {
    const Color c = probe.lookup({{0.3f, 0.6f}, p});
    return {c.x, c.y};
}

#define EXPECT_ST_NEAR(probe, p, s, t)           \
    do {                                         \
        const Vec2 st_ = stAt(*(probe), (p));    \
        EXPECT_NEAR(st_.x, (s), 1e-5f) << "s";   \
        EXPECT_NEAR(st_.y, (t), 1e-5f) << "t";   \
    } while (0)

TEST(TextureMappings, BilerpBlendsItsCornersAtTheSurfacesUv) {
    auto probe = stProbe(UvMapping{});
    const Color c = probe->lookup({{0.3f, 0.6f}, Vec3(9.0f)});
    EXPECT_VEC3_NEAR(c, Color(0.3f, 0.6f, 0), 1e-6);
    EXPECT_VEC3_NEAR(probe->average(), Color(0.5f, 0.5f, 0), 1e-5);
}

// pbrt-v4's SphericalMapping: s = theta / pi from +z, t = phi / 2pi about z from +x, of the
// direction from the texture space's origin, here placed at (1, 2, 3) in the world.
TEST(TextureMappings, SphericalReadsTheDirectionFromTheTexturesOrigin) {
    TextureMapping m;
    m.kind = TextureMapping::Kind::Spherical;
    m.textureFromWorld = Transform::translate({-1, -2, -3});
    auto probe = stProbe(m);
    const Vec3 o{1, 2, 3};
    EXPECT_ST_NEAR(probe, o + Vec3(0, 0, 2), 0.0f, 0.0f);
    EXPECT_ST_NEAR(probe, o + Vec3(3, 0, 0), 0.5f, 0.0f);
    EXPECT_ST_NEAR(probe, o + Vec3(0, 0.5f, 0), 0.5f, 0.25f);
    EXPECT_ST_NEAR(probe, o + Vec3(-1, 0, 0), 0.5f, 0.5f);
    EXPECT_ST_NEAR(probe, o + Vec3(0, -1, 0), 0.5f, 0.75f);
    // 60 degrees from +z, 45 degrees about it.
    const float s60 = std::sin(kPi / 3), c60 = std::cos(kPi / 3);
    EXPECT_ST_NEAR(probe, o + Vec3(s60 * std::sqrt(0.5f), s60 * std::sqrt(0.5f), c60) * 4.0f, 1.0f / 3.0f, 0.125f);
    // Where the mapping does not say what part of the pattern is seen: the pattern's mean.
    EXPECT_VEC3_NEAR(probe->average(), Color(0.5f, 0.5f, 0), 1e-6);
}

// pbrt-v4's CylindricalMapping: s = (pi + atan2(y, x)) / 2pi, t = z, in the texture's space
// (here turned a quarter about x: the world's +y is its +z, the world's -z its +y).
TEST(TextureMappings, CylindricalReadsTheAngleAboutZAndTheHeight) {
    TextureMapping m;
    m.kind = TextureMapping::Kind::Cylindrical;
    m.textureFromWorld = Transform::rotate({1, 0, 0}, -90).inverse();
    auto probe = stProbe(m);
    EXPECT_ST_NEAR(probe, Vec3(2, 0.25f, 0), 0.5f, 0.25f);    // texture +x: atan2 0
    EXPECT_ST_NEAR(probe, Vec3(0, 0.5f, -1), 0.75f, 0.5f);    // texture +y
    EXPECT_ST_NEAR(probe, Vec3(0, 0.75f, 3), 0.25f, 0.75f);   // texture -y
}

// pbrt-v4's PlanarMapping: s and t the point's components along two axes, then offset.
TEST(TextureMappings, PlanarProjectsOntoTwoAxes) {
    TextureMapping m;
    m.kind = TextureMapping::Kind::Planar;
    m.planarS = {1, 0, 0};
    m.planarT = {0, 0, 1};
    m.uv.offset = {0.1f, 0.2f};
    auto probe = stProbe(m);
    EXPECT_ST_NEAR(probe, Vec3(0.2f, 5, 0.5f), 0.3f, 0.7f);
    EXPECT_ST_NEAR(probe, Vec3(0.5f, -3, 0.1f), 0.6f, 0.3f);
}

TEST(TextureMappings, SolidCheckerboardAlternatesInAllThreeAxes) {
    auto t = makeSolidCheckerboardTexture(Color(1.0f), Color(0.0f), Transform());
    EXPECT_EQ(t->lookup({{}, Vec3(0.5f, 0.5f, 0.5f)}).x, 1.0f);
    EXPECT_EQ(t->lookup({{}, Vec3(1.5f, 0.5f, 0.5f)}).x, 0.0f);
    EXPECT_EQ(t->lookup({{}, Vec3(1.5f, 1.5f, 0.5f)}).x, 1.0f);
    EXPECT_EQ(t->lookup({{}, Vec3(1.5f, 1.5f, 1.5f)}).x, 0.0f);
    EXPECT_EQ(t->lookup({{}, Vec3(-0.5f, 0.5f, 0.5f)}).x, 0.0f);
    EXPECT_EQ(t->lookup({{}, Vec3(1e12f, 0.5f, 0.5f)}).x, 1.0f);  // far away: no overflow
    EXPECT_EQ(t->lookup({{0.7f, 0.2f}, Vec3(0.5f, 0.5f, 0.5f)}).x, 1.0f);  // uv plays no part
    EXPECT_VEC3_NEAR(t->average(), Color(0.5f), 0);
    // Cells of 2 units: the texture's space scaled by 2 in the world.
    auto big = makeSolidCheckerboardTexture(Color(1.0f), Color(0.0f), Transform::scale(Vec3(2.0f)).inverse());
    EXPECT_EQ(big->lookup({{}, Vec3(1.5f, 0.5f, 0.5f)}).x, 1.0f);
    EXPECT_EQ(big->lookup({{}, Vec3(2.5f, 0.5f, 0.5f)}).x, 0.0f);
}

// Perlin noise's defining properties: zero at every lattice point, where its gradient is
// one of the twelve edge directions of a cube (two components +-1, one 0); bounded; a
// period of 256; mean zero.
TEST(PerlinNoise, ZeroOnTheLatticeWithCubeEdgeGradients) {
    constexpr float h = 1e-3f;
    for (int i = -3; i < 40; i += 3)
        for (int j = -5; j < 20; j += 5)
            for (int k = 0; k < 3; ++k) {
                const Vec3 p{float(i), float(j), float(k)};
                EXPECT_EQ(perlinNoise(p), 0.0f);
                const Vec3 g{(perlinNoise(p + Vec3(h, 0, 0)) - perlinNoise(p - Vec3(h, 0, 0))) / (2 * h),
                             (perlinNoise(p + Vec3(0, h, 0)) - perlinNoise(p - Vec3(0, h, 0))) / (2 * h),
                             (perlinNoise(p + Vec3(0, 0, h)) - perlinNoise(p - Vec3(0, 0, h))) / (2 * h)};
                int ones = 0, zeros = 0;
                for (int c = 0; c < 3; ++c) {
                    if (std::abs(std::abs(g[c]) - 1) < 1e-2f) ++ones;
                    if (std::abs(g[c]) < 1e-2f) ++zeros;
                }
                EXPECT_EQ(ones, 2) << i << " " << j << " " << k;
                EXPECT_EQ(zeros, 1) << i << " " << j << " " << k;
            }
    double sum = 0, largest = 0;
    constexpr int n = 64;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Vec3 p = Vec3(i + 0.37f, j + 0.61f, k + 0.13f) * 0.5f;
                const float v = perlinNoise(p);
                sum += v;
                largest = std::max(largest, double(std::abs(v)));
                if (i < 4 && j < 4) EXPECT_NEAR(perlinNoise(p + Vec3(256, -512, 256)), v, 1e-4f);
            }
    EXPECT_LE(largest, 1.0);
    EXPECT_GT(largest, 0.5);
    EXPECT_NEAR(sum / (double(n) * n * n), 0.0, 0.01);
}

TEST(PerlinNoise, FractalSumsAddOctavesAtTwiceTheFrequency) {
    for (Vec3 p : {Vec3(0.3f, 1.7f, -2.2f), Vec3(10.1f, 0.4f, 3.9f)}) {
        const float n0 = perlinNoise(p), n1 = perlinNoise(p * 1.99f), n2 = perlinNoise(p * (1.99f * 1.99f));
        EXPECT_EQ(fractalBrownianMotion(p, 0.6f, 1), n0);
        EXPECT_NEAR(fractalBrownianMotion(p, 0.6f, 3), n0 + 0.6f * n1 + 0.36f * n2, 1e-6f);
        // pbrt-v4's turbulence stands 0.2 for each octave's |noise| past the last.
        EXPECT_NEAR(turbulence(p, 0.6f, 2), std::abs(n0) + 0.6f * std::abs(n1) + 0.36f * 0.2f, 1e-6f);
    }
}

TEST(NoiseTextures, ReadTheNoiseAtThePointInTheirSpace) {
    const Transform textureFromWorld = Transform::scale(Vec3(4.0f));  // the pattern four times finer
    const Vec3 p{0.31f, -0.72f, 1.05f};
    const TexturePoint at{{0.5f, 0.5f}, p};
    EXPECT_EQ(makeFbmTexture(textureFromWorld, 5, 0.4f)->lookup(at).x, fractalBrownianMotion(p * 4.0f, 0.4f, 5));
    EXPECT_EQ(makeWrinkledTexture(textureFromWorld, 5, 0.4f)->lookup(at).y, turbulence(p * 4.0f, 0.4f, 5));
    const float windy = std::abs(fractalBrownianMotion(p * 0.4f, 0.5f, 3)) * fractalBrownianMotion(p * 4.0f, 0.5f, 6);
    EXPECT_NEAR(makeWindyTexture(textureFromWorld)->lookup(at).z, windy, 1e-7f);
    // fbm is centred on 0; turbulence's mean is about that of |noise| (~0.2) over its octaves.
    EXPECT_NEAR(makeFbmTexture(Transform(), 8, 0.5f)->average().x, 0.0f, 0.03f);
    const float wrinkled = makeWrinkledTexture(Transform(), 8, 0.5f)->average().x;
    EXPECT_GT(wrinkled, 0.2f);
    EXPECT_LT(wrinkled, 0.5f);
}

// pbrt-v4's polka dots: cells about integer (s, t), a dot of radius 0.35 where the noise at
// the cell's centre is positive (here 392 of 1,024 cells), shifted by noise up to 0.15.
TEST(NoiseTextures, DotsSitInTheirCellsWhereTheNoiseSays) {
    auto dots = makeDotsTexture(Color(1.0f), Color(0.0f), UvMapping{});
    int cellsWithDots = 0;
    for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 32; ++i) {
            const bool dotted = perlinNoise({i + 0.5f, j + 0.5f, 0.5f}) > 0;
            cellsWithDots += dotted;
            // The dot's centre moves by at most 0.15: a point 0.19 from the cell's centre
            // is inside a dot, one 0.49 away never.
            EXPECT_EQ(dots->lookup({{i + 0.19f, float(j)}, {}}).x, dotted ? 1.0f : 0.0f) << i << " " << j;
            EXPECT_EQ(dots->lookup({{i + 0.49f, j + 0.49f}, {}}).x, 0.0f);
        }
    EXPECT_GT(cellsWithDots, 1024 * 0.3);
    EXPECT_LT(cellsWithDots, 1024 * 0.7);
    // pi 0.35^2 = 0.385 of a dotted cell.
    EXPECT_NEAR(dots->average().x, 0.385f * cellsWithDots / 1024.0f, 0.03f);
}

// A bump read at the point has a slope: the step in u moves the point by dp/du too, so the
// normal tilts against the height's gradient along the surface.
TEST(NoiseTextures, ASolidHeightBendsTheNormalByItsGradient) {
    const FloatParam height(makeFbmTexture(Transform(), 4, 0.5f));
    const Vec3 n{0, 0, 1};
    const SurfaceTangents tangents{{0.5f, 0, 0}, {0, 0.5f, 0}};  // u and v run along x and y
    for (Vec3 p : {Vec3(0.3f, 0.45f, 0.2f), Vec3(2.6f, -1.3f, 0.7f)}) {
        const TexturePoint at{{0.1f, 0.1f}, p};
        const Vec3 bent = bumpedNormal(height, at, n, n, tangents);
        const float h = height.eval(at);
        const float dhdx = (height.eval({{}, p + Vec3(0.5f * kBumpStep, 0, 0)}) - h) / (0.5f * kBumpStep);
        const float dhdy = (height.eval({{}, p + Vec3(0, 0.5f * kBumpStep, 0)}) - h) / (0.5f * kBumpStep);
        const Vec3 expected = normalize(Vec3(-dhdx, -dhdy, 1));
        EXPECT_GT(std::abs(dhdx) + std::abs(dhdy), 0.05f);
        EXPECT_VEC3_NEAR(bent, expected, 1e-3);
    }
}

TEST(TextureMappings, SceneJsonReadsMappingsAndSolidTextures) {
    Json doc = fullScene();
    doc["materials"]["white"]["albedo"] = Json::parse(R"({"type": "checkerboard", "even": [0.8, 0.8, 0.8],
        "odd": [0.1, 0.1, 0.1], "mapping": {"type": "solid", "transform": {"scale": 2}}})");
    doc["materials"]["wood"]["albedo"] = Json::parse(R"({"type": "bilerp", "v00": [0, 0, 0], "v01": [0, 1, 0],
        "v10": [1, 0, 0], "v11": [1, 1, 0], "uv_offset": [0.25, 0],
        "mapping": {"type": "planar", "s": [1, 0, 0], "t": [0, 0, 1], "transform": {"translate": [0, 0, -1]}}})");
    doc["materials"]["gloss"]["albedo"] = Json::parse(R"({"type": "fbm", "octaves": 3, "roughness": 0.7})");
    SceneDescription s = load(doc);
    EXPECT_EQ(s.materials[0]->tint().eval({{}, Vec3(1.5f, 0.5f, 0.5f)}).x, 0.8f);
    EXPECT_EQ(s.materials[0]->tint().eval({{}, Vec3(2.5f, 0.5f, 0.5f)}).x, 0.1f);
    EXPECT_VEC3_NEAR(s.materials[1]->tint().eval({{}, Vec3(0.5f, 7, -0.6f)}), Color(0.75f, 0.4f, 0), 1e-6);
    const Vec3 p{0.2f, 0.4f, 0.6f};
    EXPECT_NEAR(s.materials[5]->tint().eval({{}, p}).x, fractalBrownianMotion(p, 0.7f, 3), 1e-7f);

    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "fbm", "uv_scale": [2, 2]})"); },
                "materials.white.albedo.uv_scale", "a solid texture is read at the point, not at uv");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "fbm", "octaves": 0})"); },
                "materials.white.albedo.octaves", "must be an integer in [1, 30]");
    expectError(
        [](Json& d) {
            d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "image", "file": "textures/wood.png",
                "mapping": {"type": "conical"}})");
        },
        "materials.white.albedo.mapping.type",
        "unknown mapping type \"conical\" (expected one of uv, spherical, cylindrical, planar)");
    expectError(
        [](Json& d) {
            d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "dots", "inside": [1, 1, 1],
                "outside": [0, 0, 0], "mapping": {"type": "solid"}})");
        },
        "materials.white.albedo.mapping.type",
        "unknown mapping type \"solid\" (expected one of uv, spherical, cylindrical, planar)");
}

// pbrt-v4's textures that read the point arrive with the CTM at their Texture directive as
// the placement of their space.
// pbrt-v4's marble: its colour ramp is a cubic Bezier spline over nine colours, six segments
// of four control points; the texture reads it at 1/2 + sin(y + variation fbm) / 2 of the
// point scaled, times 1.5.
TEST(NoiseTextures, MarbleFollowsItsSplineOfTheVeinsBentByNoise) {
    const Color grey(.58f, .58f, .6f);
    EXPECT_EQ(marbleSpline(0.0f), grey);  // the first control point
    EXPECT_NEAR(marbleSpline(1.0f).z, grey.z, 1e-6f);  // the last segment ends on the last
    // t = 1/2 starts the fourth segment, on its first control point (0.5, 0.5, 0.5).
    EXPECT_EQ(marbleSpline(0.5f), Color(0.5f));
    // Half way along the fourth segment: (c3 + 3 c4 + 3 c5 + c6) / 8.
    const Color half = marbleSpline(3.5f / 6.0f);
    EXPECT_NEAR(half.x, (0.5f + 3 * 0.6f + 3 * 0.58f + 0.58f) / 8, 1e-6f);
    EXPECT_NEAR(half.y, (0.5f + 3 * 0.59f + 3 * 0.58f + 0.58f) / 8, 1e-6f);
    EXPECT_NEAR(half.z, (0.5f + 3 * 0.58f + 3 * 0.6f + 0.6f) / 8, 1e-6f);
    // The slate blue (0.2, 0.2, 0.33) pulls the sixth segment's middle down.
    EXPECT_LT(marbleSpline(5.5f / 6.0f).x, 0.45f);

    const Transform textureFromWorld = Transform::scale(Vec3(2.0f));
    const float scale = 3.0f, variation = 0.7f;
    const auto marble = makeMarbleTexture(textureFromWorld, 6, 0.45f, scale, variation);
    for (Vec3 p : {Vec3(0.31f, -0.72f, 1.05f), Vec3(-2.4f, 0.13f, 0.5f)}) {
        const Vec3 q = p * (2.0f * scale);
        const float t = 0.5f + 0.5f * std::sin(q.y + variation * fractalBrownianMotion(q, 0.45f, 6));
        const Color expected = marbleSpline(t) * 1.5f;
        const Color got = marble->lookup({{0.5f, 0.5f}, p});
        EXPECT_NEAR(got.x, expected.x, 1e-5f);
        EXPECT_NEAR(got.z, expected.z, 1e-5f);
    }
    // Over a large region the veins average to about 1.5 times the ramp's mean grey.
    const Color mean = makeMarbleTexture(Transform(), 8, 0.5f, 1.0f, 0.2f)->average();
    EXPECT_GT(mean.x, 1.5f * 0.45f);
    EXPECT_LT(mean.x, 1.5f * 0.6f);
    EXPECT_GT(mean.z, mean.x);  // bluish where the slate shows
}

TEST(NoiseTextures, MarbleInTheSceneFileAndThePbrtImport) {
    Json doc = fullScene();
    doc["materials"]["white"]["albedo"] =
        Json::parse(R"({"type": "marble", "octaves": 4, "scale": 2.5, "variation": 0.3, "mapping": {"type": "solid"}})");
    SceneDescription scene = load(doc);
    const Vec3 p{0.2f, 0.4f, 0.6f};
    const Vec3 q = p * 2.5f;
    const Color expected = marbleSpline(0.5f + 0.5f * std::sin(q.y + 0.3f * fractalBrownianMotion(q, 0.5f, 4))) * 1.5f;
    EXPECT_VEC3_NEAR(scene.materials[0]->tint().eval({{}, p}), expected, 1e-5);
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "marble", "variation": -1})"); },
                "materials.white.albedo.variation", "must be >= 0");
    expectError([](Json& d) { d["materials"]["white"]["albedo"] = Json::parse(R"({"type": "marble", "scale": 0})"); },
                "materials.white.albedo.scale", "must be > 0");

    using namespace pbrt_import;
    const ImportedScene s = import(R"(
Scale 2 2 2
Texture "stone" "spectrum" "marble" "integer octaves" 5 "float variation" 0.5 "float scale" 4
MakeNamedMaterial "floor" "string type" "diffuse" "texture reflectance" "stone"
)");
    const Json scaled = Json::parse(R"({"matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]})");
    EXPECT_EQ(s.document["materials"]["floor"]["albedo"],
              (Json{{"type", "marble"}, {"octaves", 5}, {"roughness", 0.5}, {"scale", 4.0}, {"variation", 0.5},
                    {"mapping", {{"type", "solid"}, {"transform", scaled}}}}));
    // pbrt-v4 has no float marble.
    EXPECT_STREQ(importError(kHeader + "\nTexture \"m\" \"float\" \"marble\"\n").what(),
                 "bad.pbrt:13: Texture \"m\": class \"marble\" is not supported (photon imports imagemap, checkerboard, "
                 "bilerp, dots, fbm, wrinkled, windy, marble, scale, mix, directionmix, constant)");
}

// pbrt-v4's directionmix: `along` weighted by |n . direction| at the surface's normal n,
// `across` by the rest, whichever way n points.
TEST(DirectionMix, WeighsItsTwoSidesByTheNormalsCosineToTheDirection) {
    const auto t = makeDirectionMixTexture(Color(1, 0, 0), Color(0, 0, 1), Vec3(0, 0, 2));
    EXPECT_EQ(t->lookup({{}, Vec3(5.0f), Vec3(0, 0, -1)}), Color(1, 0, 0));
    EXPECT_EQ(t->lookup({{}, Vec3(5.0f), Vec3(1, 0, 0)}), Color(0, 0, 1));
    EXPECT_VEC3_NEAR(t->lookup({{}, Vec3(5.0f), Vec3(0, 0.6f, 0.8f)}), Color(0.8f, 0, 0.2f), 1e-6);
    // Over a surface facing every way alike, |cos| averages 1/2.
    EXPECT_VEC3_NEAR(t->average(), Color(0.5f, 0, 0.5f), 1e-6);
}

// The normal reaches the texture from each integrator: a plane (normal +y) under a point
// light whose albedo is a direction mix at cos 0.6 renders as the plane of the mixed albedo,
// 0.6 x 0.7 + 0.4 x 0.1 = 0.46, by the path tracer's shading points and by SPPM's photons
// (their tint where they land) and visible points.
TEST(DirectionMix, ThePlanesNormalReachesItFromTheIntegrators) {
    const ColorParam mixed(makeDirectionMixTexture(Color(0.7f), Color(0.1f), Vec3(0, 0.6f, 0.8f)));
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        auto render = [&](bool textured) {
            SceneDescription d = test::pointLightPlane(0.46f, 10.0f, 1.0f, 16, 2.0f);
            if (textured) d.materials[0] = makeDiffuse(mixed);
            d.render.integrator = kind;
            d.render.direct = DirectLighting::Photons;
            d.render.passes = 16;
            d.render.adaptivePhotons = false;
            d.render.photonsPerPass = 20000;
            return test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
        };
        const Color textured = render(true), plain = render(false);
        EXPECT_NEAR(textured.y, plain.y, 0.01f * plain.y) << (kind == IntegratorKind::Path ? "path" : "sppm");
    }
    // And the scene file's form.
    Json doc = fullScene();
    doc["materials"]["white"]["albedo"] = Json::parse(
        R"({"type": "direction_mix", "along": [0.7, 0.7, 0.7], "across": [0.1, 0.1, 0.1], "direction": [0, 3, 4]})");
    SceneDescription scene = load(doc);
    EXPECT_VEC3_NEAR(scene.materials[0]->tint().eval({{}, Vec3(0.0f), Vec3(0, 1, 0)}), Color(0.46f), 1e-6);
    expectError(
        [](Json& d) {
            d["materials"]["white"]["albedo"] =
                Json::parse(R"({"type": "direction_mix", "along": [1, 1, 1], "across": [0, 0, 0], "direction": [0, 0, 0]})");
        },
        "materials.white.albedo.direction", "must not be the zero vector");
}

TEST(DirectionMix, PbrtImportTurnsTheDirectionByTheCtm) {
    using namespace pbrt_import;
    const ImportedScene s = import(R"(
Texture "rock" "spectrum" "imagemap" "string filename" "rock.png"
AttributeBegin
Rotate 90 0 0 1
Texture "snow" "spectrum" "directionmix" "rgb tex1" [1 1 1] "texture tex2" "rock" "vector3 dir" [0 2 0]
AttributeEnd
Texture "f" "float" "directionmix"
MakeNamedMaterial "ground" "string type" "diffuse" "texture reflectance" "snow"
MakeNamedMaterial "rough" "string type" "conductor" "texture roughness" "f"
)");
    const Json& snow = s.document["materials"]["ground"]["albedo"];
    EXPECT_EQ(snow["type"], "direction_mix");
    EXPECT_EQ(snow["along"], Json::parse("[1, 1, 1]"));
    EXPECT_EQ(snow["across"]["type"], "image");
    // +y turned 90 degrees about z is -x.
    EXPECT_NEAR(snow["direction"][0].get<double>(), -1.0, 1e-6);
    EXPECT_NEAR(snow["direction"][1].get<double>(), 0.0, 1e-6);
    // pbrt-v4's defaults: tex1 0, tex2 1, dir +y.
    EXPECT_EQ(s.document["materials"]["rough"]["uroughness"],
              (Json{{"type", "direction_mix"}, {"along", 0.0}, {"across", 1.0}, {"direction", {0.0, 1.0, 0.0}}}));
}

TEST(TextureMappings, PbrtImportKeepsMappingsAndTheTexturesSpace) {
    using namespace pbrt_import;
    const ImportedScene s = import(R"(
AttributeBegin
Translate 0 0 -1
Texture "sph" "spectrum" "imagemap" "string filename" "t.png" "string mapping" "spherical"
Texture "pl" "float" "bilerp" "string mapping" "planar" "vector3 v1" [0 0 1] "vector3 v2" [1 0 0] "float udelta" 0.5
Texture "box" "spectrum" "checkerboard" "integer dimension" 3 "rgb tex1" [1 1 1] "rgb tex2" [0 0 0]
Scale 4 4 4
Texture "bumps" "float" "wrinkled" "integer octaves" 4 "float roughness" 0.6
Texture "dots" "spectrum" "dots" "string mapping" "cylindrical" "rgb inside" [1 0 0]
AttributeEnd
Texture "waves" "float" "windy"
MakeNamedMaterial "a" "string type" "diffuse" "texture reflectance" "sph"
MakeNamedMaterial "b" "string type" "conductor" "texture roughness" "pl"
MakeNamedMaterial "c" "string type" "diffuse" "texture reflectance" "box" "texture displacement" "bumps"
MakeNamedMaterial "d" "string type" "diffuse" "texture reflectance" "dots" "texture displacement" "waves"
)");
    const Json& m = s.document["materials"];
    const Json translate = Json::parse(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 0, 1]})");
    // Translate, then Scale: the scale applies first, in the translated frame.
    const Json scaled = Json::parse(R"({"matrix": [4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 4, -1, 0, 0, 0, 1]})");
    EXPECT_EQ(m["a"]["albedo"]["mapping"], (Json{{"type", "spherical"}, {"transform", translate}}));
    EXPECT_EQ(m["b"]["uroughness"]["mapping"],
              (Json{{"type", "planar"}, {"transform", translate}, {"s", {0, 0, 1}}, {"t", {1, 0, 0}}}));
    EXPECT_EQ(m["b"]["uroughness"]["uv_offset"], Json::parse("[0.5, 0]"));
    EXPECT_EQ(m["b"]["uroughness"]["v11"], 1.0);
    EXPECT_EQ(m["c"]["albedo"]["mapping"], (Json{{"type", "solid"}, {"transform", translate}}));
    EXPECT_EQ(m["c"]["bump"],
              (Json{{"type", "wrinkled"}, {"octaves", 4}, {"roughness", 0.6}, {"mapping", {{"type", "solid"}, {"transform", scaled}}}}));
    EXPECT_EQ(m["d"]["albedo"]["type"], "dots");
    EXPECT_EQ(m["d"]["albedo"]["mapping"], (Json{{"type", "cylindrical"}, {"transform", scaled}}));
    EXPECT_EQ(m["d"]["bump"], (Json{{"type", "windy"}, {"mapping", {{"type", "solid"}}}}));

    const SceneError e = importError(kHeader + R"(
Texture "n" "float" "fbm" "float roughness" 1.5
)");
    EXPECT_STREQ(e.what(), "bad.pbrt:13: Texture \"n\": \"roughness\" must be in [0, 1]");
}

}  // namespace
}  // namespace photon::test
