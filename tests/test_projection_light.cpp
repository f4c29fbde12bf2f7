// A slide projector (lights/projection_light.cpp, pbrt-v4's projection light): its power
// and its photons against the texels' solid angles, the slide it draws on a plane by shadow
// rays against I(w) cos / r^2, photons against shadow rays, and the scene format.
#include <gtest/gtest.h>
#include <cmath>
#include <memory>
#include <vector>
#include "camera/camera.h"
#include "lights/light_factories.h"
#include "math/plane_solid_angle.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/image_texture.h"

namespace photon::projection_light_tests {
namespace {

constexpr int kWidth = 6, kHeight = 4;  // the slide, wider than high
constexpr float kRho = 0.5f, kIntensity = 10.0f, kFov = 60;
constexpr int kResolution = 48;

// Texels that step across the columns and down the rows, one black.
std::shared_ptr<const ImageTexture> slide() {
    std::vector<Color> texels;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            texels.push_back(x == 2 && y == 1 ? Color(0.0f) : Color(0.2f + 0.3f * float(x), 0.5f, 0.2f + 0.4f * float(y)));
    return std::make_shared<const ImageTexture>(kWidth, kHeight, std::move(texels));
}

// 1 m over the plane of test::pointLightPlane, projecting down (+z to -y), its image's top
// toward -z (the frame's +y turned by the same rotation).
LightDescription projector() {
    LightDescription l;
    l.kind = LightDescription::Kind::Projection;
    l.position = {0, 1, 0};
    l.intensity = Color(kIntensity);
    l.projectionFovDegrees = kFov;
    l.environment.image = slide();
    l.environment.toWorld = Transform::rotate({1, 0, 0}, 90);
    return l;
}

// The slide's half extents on the plane at distance 1: the shorter side (height) spans kFov.
const float kHalfY = std::tan(0.5f * kFov * kPi / 180), kHalfX = kHalfY * kWidth / kHeight;

// The texel a light-frame direction passes through (-1 outside), and its value.
Color slideToward(Vec3 local) {
    if (local.z <= 0) return Color(0.0f);
    const float x = local.x / local.z, y = local.y / local.z;
    if (std::abs(x) >= kHalfX || std::abs(y) >= kHalfY) return Color(0.0f);
    return slide()->texel(int((x + kHalfX) / (2 * kHalfX) * kWidth), int((kHalfY - y) / (2 * kHalfY) * kHeight));
}

// Power: the intensity times each texel times its solid angle; photons carry it in all and
// their flux-weighted mean direction is the slide's, summed texel by texel over 32 x 32
// pieces of each.
TEST(ProjectionLight, PhotonsCarryThePowerAsTheSlideSpreadsIt) {
    const std::unique_ptr<Light> light = makeProjectionLight(projector());
    Color expectedPower(0.0f);
    Vec3 expectedMoment(0.0f);
    constexpr int kPieces = 32;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int j = 0; j < kPieces; ++j)
                for (int i = 0; i < kPieces; ++i) {
                    const double x0 = -kHalfX + 2 * kHalfX * (x + double(i) / kPieces) / kWidth;
                    const double x1 = -kHalfX + 2 * kHalfX * (x + double(i + 1) / kPieces) / kWidth;
                    const double y1 = kHalfY - 2 * kHalfY * (y + double(j) / kPieces) / kHeight;
                    const double y0 = kHalfY - 2 * kHalfY * (y + double(j + 1) / kPieces) / kHeight;
                    const Color piece = slide()->texel(x, y) * float(kIntensity * rectangleSolidAngle(x0, x1, y0, y1));
                    expectedPower += piece;
                    const Vec3 w = Transform::rotate({1, 0, 0}, 90).vector(
                        normalize(Vec3(float(0.5 * (x0 + x1)), float(0.5 * (y0 + y1)), 1)));
                    expectedMoment += w * piece.y;
                }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(light->power()[c], expectedPower[c], 1e-4f * expectedPower[c]) << c;
    constexpr int kStrata = 256;
    Color total(0.0f);
    Vec3 moment(0.0f);
    for (int j = 0; j < kStrata; ++j)
        for (int i = 0; i < kStrata; ++i) {
            const auto photon = light->emitPhoton({0.5f, 0.5f}, {(i + 0.5f) / kStrata, (j + 0.5f) / kStrata});
            ASSERT_TRUE(photon);
            const Color flux = photon->flux / float(kStrata * kStrata);
            total += flux;
            moment += photon->direction * flux.y;
        }
    // Drawn by luminance, the photons' colours vary: their sums per channel within 1%.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], expectedPower[c], 1e-2f * expectedPower[c]) << c;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(moment[a], expectedMoment[a], 5e-3f * expectedPower.y) << "axis " << a;
}

// rho / pi I(w) cos theta / r^2 where the camera ray through film point (x, y) meets the plane.
Color analyticRadiance(const Camera& camera, float x, float y) {
    const Vec3 toP = test::planePointSeen(camera, x, y) - Vec3(0, 1, 0);
    const float r2 = lengthSquared(toP), cosTheta = 1.0f / std::sqrt(r2);
    // The frame turned back: the rotation takes the light's (x, y, z) to the world's
    // (x, -z, y), so the world's (x, y, z) is the light's (x, z, -y).
    const Vec3 local(toP.x, toP.z, -toP.y);
    return slideToward(local) * (kRho / kPi * kIntensity * cosTheta / r2);
}

// Shadow rays draw the slide: every 4 x 4 block within 1% of the analytic mean, per channel.
TEST(ProjectionLight, ShadowRaysDrawTheSlide) {
    const SceneDescription d = test::lightOverPlane(projector(), kRho, kResolution, DirectLighting::LightSampling, 64, 1000);
    const Camera camera(d.camera);
    const test::LitAndDark blocks = test::expectBlocksMatch(
        test::renderImage(d), [&](float x, float y) { return analyticRadiance(camera, x, y); }, 0.01f);
    EXPECT_GT(blocks.lit, 20);
    EXPECT_GT(blocks.dark, 20);
}

TEST(ProjectionLight, PhotonsDrawWhatShadowRaysDraw) {
    test::expectPhotonsDrawWhatShadowRaysDraw(projector(), kRho, kResolution);
}

// {"type": "projection", "position", "intensity", "image", "fov", "rotate" or "matrix"}.
TEST(ProjectionLight, TheSceneFormatMakesAProjector) {
    Json doc = test::fullScene();
    doc["lights"] = Json::array({{{"type", "projection"}, {"position", {0, 1, 0}}, {"intensity", {2, 2, 2}},
                                  {"image", "textures/wood.png"}, {"fov", 30}}});
    const SceneDescription d = test::load(doc);
    ASSERT_EQ(d.lights[0].kind, LightDescription::Kind::Projection);
    const std::unique_ptr<Light> light = makeProjectionLight(d.lights[0]);
    // The 2 x 2 texture's top-left texel (red) toward the frame's -x, +y quadrant; nothing
    // beyond the 30 degrees.
    const Color red = light->emittedDensity(normalize(Vec3(-0.1f, 0.1f, 1)));
    EXPECT_NEAR(red.x, 2.0f, 1e-5f);
    EXPECT_NEAR(red.y, 0.0f, 1e-5f);
    EXPECT_TRUE(isBlack(light->emittedDensity(normalize(Vec3(0, 0.3f, 1)))));
    test::expectError([&](Json& bad) { bad["lights"] = doc["lights"], bad["lights"][0]["layout"] = "equal_area"; },
                      "lights[0].layout", "does not apply to a projection (its image lies flat)");
    test::expectError([&](Json& bad) { bad["lights"] = doc["lights"], bad["lights"][0]["fov"] = 180; }, "lights[0].fov",
                      "must be in (0, 180)");
}

}  // namespace
}  // namespace photon::projection_light_tests
