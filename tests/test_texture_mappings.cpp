// Textures read at the hit point: the spherical, cylindrical and planar mappings, the solid
// checkerboard and pbrt-v4's noise textures, against their definitions; the point reaching
// them from the integrators (a cut-out and a bump), the scene JSON and the pbrt import.
#include <cmath>
#include "materials/normal_map.h"
#include "pbrt_import_fixture.h"
#include "scene_loader_fixture.h"
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
