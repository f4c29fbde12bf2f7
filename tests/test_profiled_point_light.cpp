// A point light with an intensity profile (lights/profiled_point_light.cpp, pbrt-v4's
// goniometric light): its power and its photons against the image's integral, the profile it
// draws on a plane by shadow rays against I(w) cos / r^2, and by photons against shadow rays.
#include <gtest/gtest.h>
#include <cmath>
#include <memory>
#include <vector>
#include "camera/camera.h"
#include "lights/light_factories.h"
#include "math/equal_area.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/image_texture.h"

namespace photon::profiled_point_light_tests {
namespace {

constexpr int kSide = 8;  // the profile's equal-area square, texels a side
constexpr float kRho = 0.5f, kIntensity = 10.0f;
constexpr int kResolution = 48;

// A grey profile whose texels step from 0.1 to 1.7 across the square's columns, with one
// black texel: uneven enough that sampling by it matters.
std::shared_ptr<const ImageTexture> profileImage() {
    std::vector<Color> texels;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) texels.push_back(Color(x == 3 && y == 4 ? 0.0f : 0.1f + 0.2f * float(x)));
    return std::make_shared<const ImageTexture>(kSide, kSide, std::move(texels));
}

// The light 1 m over the plane of test::pointLightPlane, its map's centre (+z of the
// equal-area square) turned to point down.
LightDescription profiledLight() {
    LightDescription l;
    l.kind = LightDescription::Kind::Point;
    l.position = {0, 1, 0};
    l.intensity = Color(kIntensity);
    l.environment.image = profileImage();
    l.environment.layout = EnvironmentLayout::EqualArea;
    l.environment.toWorld = Transform::rotate({1, 0, 0}, 90);  // +z to -y
    return l;
}

// The profile toward world direction w: its texel, looked up independently of the light.
float profileToward(Vec3 w) {
    const Vec3 local = normalize(Transform::rotate({1, 0, 0}, 90).inverseRotation(w));
    const Vec2 uv = equalAreaSphereToSquare(local);
    const int x = std::min(kSide - 1, int(uv.x * kSide)), y = std::min(kSide - 1, int(uv.y * kSide));
    return profileImage()->texel(x, y).x;
}

// Its power is the intensity times the image's integral (each equal-area texel 4 pi / n^2 of
// the sphere); photons carry it in all, and their flux-weighted mean direction is the
// profile's (by a midpoint rule over the sphere, 1000 x 1000 in cos theta and phi).
TEST(ProfiledPointLight, PhotonsCarryThePowerAsTheProfileSpreadsIt) {
    const std::unique_ptr<Light> light = makePointLight(profiledLight());
    double texelSum = 0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) texelSum += profileImage()->texel(x, y).x;
    const double expectedPower = kIntensity * texelSum * 4 * kPi / (kSide * kSide);
    EXPECT_NEAR(light->power().y, expectedPower, 1e-4 * expectedPower);
    constexpr int kGrid = 1000;
    double quadraturePower = 0;
    Vec3 quadratureMoment(0.0f);
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            const float cosTheta = 1 - 2 * (j + 0.5f) / kGrid, phi = 2 * kPi * (i + 0.5f) / kGrid;
            const float sinTheta = std::sqrt(std::max(0.0f, 1 - cosTheta * cosTheta));
            const Vec3 w(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
            const double intensity = kIntensity * profileToward(w) * 4 * kPi / (double(kGrid) * kGrid);
            quadraturePower += intensity;
            quadratureMoment += w * float(intensity);
        }
    EXPECT_NEAR(quadraturePower, expectedPower, 2e-3 * expectedPower);
    constexpr int kStrata = 256;
    double total = 0;
    Vec3 moment(0.0f);
    for (int j = 0; j < kStrata; ++j)
        for (int i = 0; i < kStrata; ++i) {
            const auto photon = light->emitPhoton({0.5f, 0.5f}, {(i + 0.5f) / kStrata, (j + 0.5f) / kStrata});
            ASSERT_TRUE(photon);
            const double flux = photon->flux.y / (kStrata * kStrata);
            total += flux;
            moment += photon->direction * float(flux);
        }
    EXPECT_NEAR(total, expectedPower, 1e-4 * expectedPower);
    std::printf("  mean direction x power: photons (%.3f %.3f %.3f), quadrature (%.3f %.3f %.3f)\n", moment.x, moment.y,
                moment.z, quadratureMoment.x, quadratureMoment.y, quadratureMoment.z);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(moment[a], quadratureMoment[a], 0.01 * expectedPower) << "axis " << a;
    EXPECT_GT(length(quadratureMoment), 0.1 * expectedPower);  // the profile is not balanced
}

// The radiance where the camera ray through film point (x, y) meets the plane:
// rho / pi I(w) cos theta / r^2.
double analyticRadiance(const Camera& camera, float x, float y) {
    const Vec3 toP = test::planePointSeen(camera, x, y) - Vec3(0, 1, 0);
    const float r2 = lengthSquared(toP), cosTheta = 1.0f / std::sqrt(r2);
    return kRho / kPi * kIntensity * profileToward(toP) * cosTheta / r2;
}

// Shadow rays draw the profile's texels on the plane: every 4 x 4 block's mean within 1% of
// the analytic one, where the light reaches it.
TEST(ProfiledPointLight, ShadowRaysDrawTheProfile) {
    const SceneDescription d = test::lightOverPlane(profiledLight(), kRho, kResolution, DirectLighting::LightSampling, 64, 1000);
    const Camera camera(d.camera);
    const test::LitAndDark blocks = test::expectBlocksMatch(
        test::renderImage(d), [&](float x, float y) { return Color(float(analyticRadiance(camera, x, y))); }, 0.01f);
    EXPECT_GT(blocks.lit, 100);
}

TEST(ProfiledPointLight, PhotonsDrawWhatShadowRaysDraw) {
    test::expectPhotonsDrawWhatShadowRaysDraw(profiledLight(), kRho, kResolution);
}

// In the scene format: a point light's "image" and the fields that go with it, which are
// refused without it.
TEST(ProfiledPointLight, TheSceneFormatGivesAPointLightAProfile) {
    Json doc = test::fullScene();
    doc["lights"] = Json::array({{{"type", "point"}, {"position", {0, 1, 0}}, {"intensity", {2, 2, 2}},
                                  {"image", "textures/wood.png"}, {"layout", "equal_area"}, {"scale", 0.5}}});
    const SceneDescription d = test::load(doc);
    const std::unique_ptr<Light> light = makePointLight(d.lights[0]);
    // The 2 x 2 texture's top-left texel (red: 1, 0, 0) over the square's x < 0, y < 0 quadrant.
    const Color red = light->emittedDensity(normalize(Vec3(-0.3f, -0.3f, 1)));
    EXPECT_NEAR(red.x, 1.0f, 1e-5f);
    EXPECT_NEAR(red.y, 0.0f, 1e-5f);
    test::expectError([](Json& bad) { bad["lights"][0]["scale"] = 2; }, "lights[0].scale", "is only allowed with \"image\"");
}

}  // namespace
}  // namespace photon::profiled_point_light_tests
