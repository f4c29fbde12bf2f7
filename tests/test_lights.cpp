// Each kind of light over a diffuse plane against its analytic radiance, by shadow rays
// and by photons (which tests its photon emission and power).
#include <gtest/gtest.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr float kRho = 0.5f;
constexpr int kRes = 32;

// A plane just larger than the view, so that lights emitting from the scene's bounds
// (directional, environment) put most photons where the camera looks.
SceneDescription planeUnder(LightDescription light) {
    SceneDescription d = test::pointLightPlane(kRho, 1.0f, 1.0f, kRes, 2.0f);
    d.lights = {light};
    return d;
}

// The analytic radiance L(p) averaged over the central 8x8 pixels' footprint on the plane.
template <class Radiance>
float analyticCentre(LightDescription light, Radiance radiance) {
    Camera camera(planeUnder(light).camera);
    double sum = 0;
    for (int y = 12 * 4; y < 20 * 4; ++y)
        for (int x = 12 * 4; x < 20 * 4; ++x) {
            Ray ray = camera.generateRay((x + 0.5f) / 4, (y + 0.5f) / 4, {0.5f, 0.5f});
            sum += radiance(ray.o + ray.d * (-ray.o.y / ray.d.y));
        }
    return static_cast<float>(sum / (32.0 * 32.0));
}

Color renderCentre(LightDescription light, DirectLighting direct) {
    SceneDescription d = planeUnder(light);
    d.render.direct = direct;
    d.render.passes = direct == DirectLighting::Photons ? 48 : 16;
    d.render.photonsPerPass = 100000;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    renderer.run(cancel);
    return test::meanOver(renderer.snapshot(), 12, 12, 20, 20);
}

class Lights : public ::testing::TestWithParam<DirectLighting> {};

TEST_P(Lights, SpotLightStraightBelowGivesIOverHSquared) {
    LightDescription spot;
    spot.kind = LightDescription::Kind::Spot;
    spot.position = {0, 1, 0};
    spot.direction = {0, -1, 0};
    spot.intensity = Color(10.0f);
    spot.coneAngleDegrees = 40;
    spot.falloffAngleDegrees = 30;
    // The centre is within 20 degrees of the axis, inside the full-intensity cone.
    float expected = analyticCentre(spot, [](Vec3 p) {
        float r2 = p.x * p.x + p.z * p.z + 1.0f;
        return kRho / kPi * 10.0f / r2 / std::sqrt(r2);  // cos = 1 / r
    });
    Color got = renderCentre(spot, GetParam());
    EXPECT_NEAR(got.y, expected, 0.03f * expected);
}

TEST_P(Lights, DirectionalLightGivesIrradianceTimesCosine) {
    LightDescription sun;
    sun.kind = LightDescription::Kind::Directional;
    sun.direction = {0, -1, -1};  // 45 degrees from the normal
    sun.irradiance = Color(2.0f);
    float expected = kRho / kPi * 2.0f * std::sqrt(0.5f);
    Color got = renderCentre(sun, GetParam());
    EXPECT_NEAR(got.y, expected, 0.03f * expected);
}

TEST_P(Lights, UniformEnvironmentGivesAlbedoTimesRadiance) {
    LightDescription sky;
    sky.kind = LightDescription::Kind::Environment;
    sky.radiance = Color(0.8f);
    // The plane sees the whole upper hemisphere: E = pi L, so L_out = rho L.
    float expected = kRho * 0.8f;
    Color got = renderCentre(sky, GetParam());
    EXPECT_NEAR(got.y, expected, 0.03f * expected);
}

INSTANTIATE_TEST_SUITE_P(DirectLight, Lights,
                         ::testing::Values(DirectLighting::LightSampling, DirectLighting::Photons));

}  // namespace
}  // namespace photon
