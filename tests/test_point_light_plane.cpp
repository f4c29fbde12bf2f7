// A diffuse plane under a point light has radiance rho/pi * I cos(theta) / r^2: the
// photon density estimate and the shadow-ray estimate must both reach it.
#include <gtest/gtest.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon::point_light_plane_tests {
namespace {

constexpr float kRho = 0.5f, kIntensity = 10.0f, kHeight = 1.0f;
constexpr int kResolution = 64;

// The pixel's analytic value: the radiance averaged over the pixel's area on the plane.
float analyticPixel(const Camera& camera, int x, int y) {
    const int n = 8;
    double sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Ray ray = camera.generateRay(x + (i + 0.5f) / n, y + (j + 0.5f) / n, {0.5f, 0.5f});
            float t = -ray.o.y / ray.d.y;
            Vec3 p = ray.o + ray.d * t;
            float r2 = p.x * p.x + p.z * p.z + kHeight * kHeight;
            float cosTheta = kHeight / std::sqrt(r2);
            sum += kRho / kPi * kIntensity * cosTheta / r2;
        }
    return static_cast<float>(sum / (n * n));
}

// How the plane is made: as usual; one-sided ("two_sided": false) facing the light and the
// camera; or one-sided facing away from both.
enum class Sides { Two, OneFacingLight, OneFacingAway };

Image render(DirectLighting direct, int passes, int64_t photons, KernelKind kernel = KernelKind::Uniform,
             Sides sides = Sides::Two, IntegratorKind integrator = IntegratorKind::Sppm) {
    SceneDescription d = test::pointLightPlane(kRho, kIntensity, kHeight, kResolution);
    if (sides != Sides::Two) d.materials[0] = makeOneSided(d.materials[0]);
    if (sides == Sides::OneFacingAway) d.shapes[0].flipNormals = !d.shapes[0].flipNormals;
    d.render.integrator = integrator;
    d.render.direct = direct;
    d.render.kernel = kernel;
    d.render.passes = passes;
    d.render.photonsPerPass = photons;
    // The bias the tolerances allow is that of this count in every pass (adaptive counts
    // would drop it to the floor on a 64 x 64 image with one light, leaving larger radii).
    d.render.adaptivePhotons = false;
    return test::renderImage(std::move(d));
}

// 8x8-pixel blocks at the centre, off centre and near the corners.
const int kBlocks[][2] = {{28, 28}, {40, 20}, {12, 48}, {4, 4}, {52, 52}, {20, 8}, {52, 4}, {4, 52}};

void expectBlocksMatch(const Image& image, float tolerance) {
    Camera camera(test::pointLightPlane(kRho, kIntensity, kHeight, kResolution).camera);
    for (const auto& b : kBlocks) {
        double expected = 0;
        for (int y = b[1]; y < b[1] + 8; ++y)
            for (int x = b[0]; x < b[0] + 8; ++x) expected += analyticPixel(camera, x, y) / 64.0;
        Color got = test::meanOver(image, b[0], b[1], b[0] + 8, b[1] + 8);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], expected, tolerance * expected) << "block at " << b[0] << "," << b[1];
    }
}

TEST(PointLightPlane, PhotonDensityEstimateMatchesAnalyticRadiance) {
    expectBlocksMatch(render(DirectLighting::Photons, 64, 100000), 0.03f);
}

// The biweight and cone kernels weigh photons by distance (photon_kernel.h): normalised
// right, their estimates reach the same analytic radiance; a wrong constant would be off by
// it everywhere, a wrong shape where the radiance curves.
TEST(PointLightPlane, BiweightKernelEstimateMatchesAnalyticRadiance) {
    expectBlocksMatch(render(DirectLighting::Photons, 64, 100000, KernelKind::Biweight), 0.03f);
}

TEST(PointLightPlane, ConeKernelEstimateMatchesAnalyticRadiance) {
    expectBlocksMatch(render(DirectLighting::Photons, 64, 100000, KernelKind::Cone), 0.03f);
}

// A one-sided plane facing the light is the two-sided plane; facing away, it is black to
// photons, shadow rays and the path tracer alike (its back absorbs and reflects nothing).
TEST(PointLightPlane, OneSidedPlaneIsLitOnItsFrontAndBlackBehind) {
    expectBlocksMatch(render(DirectLighting::Photons, 64, 100000, KernelKind::Uniform, Sides::OneFacingLight), 0.03f);
    expectBlocksMatch(render(DirectLighting::LightSampling, 64, 1000, KernelKind::Uniform, Sides::OneFacingLight,
                             IntegratorKind::Path),
                      0.02f);
    for (const Image& image :
         {render(DirectLighting::Photons, 4, 100000, KernelKind::Uniform, Sides::OneFacingAway),
          render(DirectLighting::LightSampling, 4, 100000, KernelKind::Uniform, Sides::OneFacingAway),
          render(DirectLighting::LightSampling, 4, 1000, KernelKind::Uniform, Sides::OneFacingAway, IntegratorKind::Path)})
        for (float v : image.rgb) ASSERT_EQ(v, 0.0f);
    // Radiosity's patches hold the light leaving one side, whatever reaches the other: it
    // refuses the scene rather than light the back.
    SceneDescription d = test::pointLightPlane(kRho, kIntensity, kHeight, 8);
    d.materials[0] = makeOneSided(d.materials[0]);
    d.render.integrator = IntegratorKind::Radiosity;
    try {
        test::renderImage(std::move(d));
        FAIL() << "radiosity rendered a one-sided plane";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "radiosity: material \"plane\" is one-sided (two_sided: false), which radiosity "
                                         "does not model; render the scene with sppm, path or photonmap");
    }
}

TEST(PointLightPlane, ShadowRaysMatchAnalyticRadiance) {
    // With direct light by shadow rays and nothing to bounce from, every pixel is exact
    // up to the pixel jitter; check single pixels too.
    Image image = render(DirectLighting::LightSampling, 16, 1000);
    Camera camera(test::pointLightPlane(kRho, kIntensity, kHeight, kResolution).camera);
    for (const auto& b : kBlocks) {
        float expected = analyticPixel(camera, b[0], b[1]);
        EXPECT_NEAR(image.at(b[0], b[1]).y, expected, 0.03f * expected);
    }
    expectBlocksMatch(image, 0.01f);
}

}  // namespace
}  // namespace photon::point_light_plane_tests
