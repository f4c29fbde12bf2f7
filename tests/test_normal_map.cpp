// Normal maps: the bent normal a texel stands for, a flat map that changes nothing, and a
// plane whose map tilts every normal by 30 degrees toward a directional light, lit exactly
// as the tilted plane would be: rho/pi E cos(angle to the bent normal), by the path tracer
// and by SPPM (whose photons carry |wi.ns| / |wi.ng|).
#include <gtest/gtest.h>
#include <cmath>
#include "materials/normal_map.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/image_texture.h"

namespace photon::normal_map_tests {
namespace {

constexpr float kRho = 0.5f, kIrradiance = 2.0f, kTilt = 30.0f * kPi / 180.0f;

std::shared_ptr<const Texture> constantMap(Vec3 t) {
    Color c(0.5f * (t.x + 1), 0.5f * (t.y + 1), 0.5f * (t.z + 1));
    return std::make_shared<ImageTexture>(1, 1, std::vector<Color>{c});
}

TEST(NormalMap, TexelToBentNormal) {
    const Vec3 n(0, 1, 0), dpdu(2, 0, 0);
    EXPECT_VEC3_NEAR(mappedNormal(*constantMap({0, 0, 1}), {0.3f, 0.3f}, n, n, dpdu), n, 1e-6);
    // x = dp/du = +x, y = n x x = -z.
    Vec3 tilted = mappedNormal(*constantMap({std::sin(kTilt), 0, std::cos(kTilt)}), {}, n, n, dpdu);
    EXPECT_VEC3_NEAR(tilted, Vec3(std::sin(kTilt), std::cos(kTilt), 0), 1e-6);
    EXPECT_VEC3_NEAR(mappedNormal(*constantMap({0, 0.6f, 0.8f}), {}, n, n, dpdu), Vec3(0, 0.8f, -0.6f), 1e-6);
    // A normal at or below the surface is not used.
    EXPECT_VEC3_NEAR(mappedNormal(*constantMap({1, 0, 0}), {}, n, n, dpdu), n, 0);
}

// A plane facing +y (u along +x) under a directional light arriving from (1, 1, 0)/sqrt 2.
SceneDescription tiltedPlane(std::shared_ptr<const Texture> map, IntegratorKind kind) {
    SceneDescription d = test::pointLightPlane(kRho, 0, 1, 16, 3.0f);
    d.lights.clear();
    LightDescription sun;
    sun.kind = LightDescription::Kind::Directional;
    sun.direction = normalize(Vec3(-1, -1, 0));
    sun.irradiance = Color(kIrradiance);
    d.lights.push_back(sun);
    if (map) d.materials[0] = makeNormalMapped(d.materials[0], std::move(map));
    d.camera = test::camera({0, 3, 0}, {0, 0, 0}, {0, 0, -1}, 20, 16, 16);
    d.render.integrator = kind;
    d.render.passes = kind == IntegratorKind::Path ? 16 : 32;
    d.render.photonsPerPass = 100000;
    d.render.adaptivePhotons = false;  // the radii, and the blur at the plane's edge, of this count
    d.render.direct = DirectLighting::Photons;  // SPPM: the light through photons alone
    return d;
}

class NormalMapRender : public testing::TestWithParam<IntegratorKind> {};

TEST_P(NormalMapRender, TiltedMapLightsLikeATiltedPlane) {
    auto map = constantMap({std::sin(kTilt), 0, std::cos(kTilt)});
    Image bent = test::renderImage(tiltedPlane(map, GetParam()));
    Image flat = test::renderImage(tiltedPlane(constantMap({0, 0, 1}), GetParam()));
    Image plain = test::renderImage(tiltedPlane(nullptr, GetParam()));
    const Vec3 toLight = normalize(Vec3(1, 1, 0));
    const float expectedBent = kRho / kPi * kIrradiance * dot(Vec3(std::sin(kTilt), std::cos(kTilt), 0), toLight);
    const float expectedFlat = kRho / kPi * kIrradiance * dot(Vec3(0, 1, 0), toLight);
    Color b = test::meanOver(bent, 0, 0, 16, 16), f = test::meanOver(flat, 0, 0, 16, 16);
    Color p = test::meanOver(plain, 0, 0, 16, 16);
    std::printf("  bent %.5f (expected %.5f)  flat map %.5f, no map %.5f (expected %.5f)\n", b.x, expectedBent, f.x, p.x,
                expectedFlat);
    // Photon density estimates blur the disc's edge a little where the plane ends; none here.
    EXPECT_NEAR(b.x, expectedBent, 0.015f * expectedBent);
    EXPECT_NEAR(f.x, expectedFlat, 0.015f * expectedFlat);
    EXPECT_NEAR(p.x, expectedFlat, 0.015f * expectedFlat);
}

INSTANTIATE_TEST_SUITE_P(Integrators, NormalMapRender, testing::Values(IntegratorKind::Path, IntegratorKind::Sppm),
                         [](const testing::TestParamInfo<IntegratorKind>& info) {
                             return info.param == IntegratorKind::Path ? std::string("Path") : std::string("Sppm");
                         });

TEST(NormalMap, SceneJsonReadsTheMapAsStored) {
    using namespace test;
    const fs::path dir = fixture().scene / "textures";
    writeImage<uint8_t>(dir / "bumps.png", 1, 1, 3, {128, 128, 255});
    Json doc = fullScene();
    doc["materials"]["white"]["normal_map"] = "textures/bumps.png";
    SceneDescription s = load(doc);
    ASSERT_TRUE(s.materials[0]->bendsNormal());
    // 128/255 read as stored is 0.502 (-> 0.004), not the sRGB-decoded 0.216 (-> -0.57).
    const Vec3 n(0, 1, 0);
    Vec3 bent = s.materials[0]->bentNormal({0.5f, 0.5f}, n, n, SurfaceTangents{{1, 0, 0}, {0, 0, -1}});
    EXPECT_VEC3_NEAR(bent, n, 0.01f);
    EXPECT_VEC3_NEAR(s.materials[0]->tint().value, Vec3(0.725f, 0.71f, 0.68f), 0);
}

}  // namespace
}  // namespace photon::normal_map_tests

namespace photon::normal_map_tests {
namespace {

// A height field rising by s per unit of u on a plane whose u runs along +x at 2 scene
// units per unit of u: the bumped normal is that of a slope rising s/2 per unit of x.
TEST(BumpMap, SlopeOfTheHeightFieldTiltsTheNormal) {
    const float s = 0.6f;
    // h(u, v) = s u, within the texture's unit square (a 2-texel ramp, bilinear between
    // the texel centres at u = 1/4 and 3/4: h = s/4 + (u - 1/4) s).
    auto ramp = std::make_shared<ImageTexture>(2, 1, std::vector<Color>{Color(s * 0.25f), Color(s * 0.75f)});
    SurfaceTangents t{{2, 0, 0}, {0, 0, -2}};
    const Vec3 n(0, 1, 0);
    Vec3 bumped = bumpedNormal(FloatParam(ramp), {0.5f, 0.5f}, n, n, t);
    EXPECT_VEC3_NEAR(bumped, normalize(Vec3(-s / 2, 1, 0)), 1e-4);
    // A constant height changes nothing; without tangents nothing can be said.
    EXPECT_VEC3_NEAR(bumpedNormal(FloatParam(0.3f), {0.5f, 0.5f}, n, n, t), n, 0);
    EXPECT_VEC3_NEAR(bumpedNormal(FloatParam(ramp), {0.5f, 0.5f}, n, n, SurfaceTangents{}), n, 0);
}

TEST(BumpMap, SceneJson) {
    using namespace test;
    writeImage<uint8_t>(fixture().scene / "textures/bumps.png", 1, 1, 3, {128, 128, 255});
    Json doc = fullScene();
    doc["materials"]["white"]["bump"] = Json::parse(R"({"type": "checkerboard", "even": 0, "odd": 0.01})");
    SceneDescription s = load(doc);
    EXPECT_TRUE(s.materials[0]->bendsNormal());
    expectError([](Json& d) {
        d["materials"]["white"]["bump"] = 0.1;
        d["materials"]["white"]["normal_map"] = "textures/bumps.png";
    }, "materials.white.bump", "cannot be given with \"normal_map\"");
}

}  // namespace
}  // namespace photon::normal_map_tests
