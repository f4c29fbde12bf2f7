// A spot light over a diffuse plane draws its falloff profile on it: radiance
// rho/pi * I * s(cos theta) * cos theta / r^2, where s is 1 inside the falloff angle, 0
// outside the cone and the smoothstep between (pbrt-v4 12.2.1). Rendered with shadow rays
// (the light's sampling) and with photons (its emission), across the whole profile.
#include <gtest/gtest.h>
#include <photon/render.h>
#include "camera/camera.h"
#include "integrators/integrator.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon::spot_light_profile_tests {
namespace {

constexpr float kRho = 0.5f, kIntensity = 10.0f, kHeight = 1.0f;
constexpr float kConeDegrees = 30, kFalloffDegrees = 15;
constexpr int kResolution = 64;

float smoothStepProfile(float cosTheta) {
    const float cosTotal = std::cos(kConeDegrees * kPi / 180), cosStart = std::cos(kFalloffDegrees * kPi / 180);
    float t = std::clamp((cosTheta - cosTotal) / (cosStart - cosTotal), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

SceneDescription spotOverPlane() {
    SceneDescription d = test::pointLightPlane(kRho, kIntensity, kHeight, kResolution);
    LightDescription& spot = d.lights[0];
    spot.kind = LightDescription::Kind::Spot;
    spot.direction = {0, -1, 0};
    spot.coneAngleDegrees = kConeDegrees;
    spot.falloffAngleDegrees = kFalloffDegrees;
    return d;
}

// The radiance where the camera ray through film point (x, y) meets the plane.
double analyticRadiance(const Camera& camera, float x, float y) {
    Ray ray = camera.generateRay(x, y, {0.5f, 0.5f});
    Vec3 p = ray.o + ray.d * (-ray.o.y / ray.d.y);
    float r2 = p.x * p.x + p.z * p.z + kHeight * kHeight;
    float cosTheta = kHeight / std::sqrt(r2);
    return kRho / kPi * kIntensity * smoothStepProfile(cosTheta) * cosTheta / r2;
}

// The radiance over the pixel rectangle [x0, x0 + 2) x [y0, y0 + 2): its mean, and the
// spread of its values, which a render's jittered samples (uniform over the pixels) see.
struct Footprint {
    double mean = 0, deviation = 0;
};
Footprint analyticBlock(const Camera& camera, int x0, int y0) {
    const int n = 16;  // points per pixel side
    double sum = 0, squares = 0;
    for (int j = 0; j < 2 * n; ++j)
        for (int i = 0; i < 2 * n; ++i) {
            double v = analyticRadiance(camera, x0 + (i + 0.5f) / n, y0 + (j + 0.5f) / n);
            sum += v;
            squares += v * v;
        }
    Footprint f;
    f.mean = sum / (4 * n * n);
    f.deviation = std::sqrt(std::max(0.0, squares / (4 * n * n) - f.mean * f.mean));
    return f;
}

Image render(DirectLighting direct, int passes, int64_t photons) {
    SceneDescription d = spotOverPlane();
    d.render.direct = direct;
    d.render.passes = passes;
    d.render.photonsPerPass = photons;
    return test::renderImage(std::move(d));
}

// The image's centre rows from the middle outwards, against the profile: full inside the
// falloff angle (r < 0.27 on the plane, 6 pixels), fading to nothing at the cone (r = 0.58,
// 13 pixels), dark beyond. Each 2x2 block's mean within `tolerance` of the analytic mean
// (or of the full value, where it is dark) plus four standard errors of `samples` jittered
// samples of it (where the profile is steep, where a block's samples fall matters), and the
// three parts all seen.
void expectProfile(const Image& image, int samples, float tolerance) {
    Camera camera(spotOverPlane().camera);
    const double full = analyticBlock(camera, 31, 31).mean;
    int inside = 0, fading = 0, dark = 0;
    for (int x = 32; x < 52; x += 2) {
        Footprint block = analyticBlock(camera, x, 31);
        const double expected = block.mean;
        const double jitter = 4 * block.deviation / std::sqrt(double(samples));
        Color got = test::meanOver(image, x, 31, x + 2, 33);
        EXPECT_NEAR(got.y, expected, tolerance * std::max(expected, 0.1 * full) + jitter) << "pixels " << x << "-" << x + 1;
        if (expected >= 0.89 * full) ++inside;  // full intensity times cos^3 theta, theta <= 15 degrees
        else if (expected > 0.001 * full) ++fading;
        else ++dark;
    }
    EXPECT_GE(inside, 2);
    EXPECT_GE(fading, 3);
    EXPECT_GE(dark, 2);
}

TEST(SpotLightProfile, ShadowRaysDrawTheSmoothstepFalloff) {
    expectProfile(render(DirectLighting::LightSampling, 64, 1000), 4 * 64, 0.01f);
}

TEST(SpotLightProfile, PhotonsDrawTheSmoothstepFalloff) {
    // The density estimate blurs the slope over the gather radius, which shrinks with passes.
    expectProfile(render(DirectLighting::Photons, 64, 100000), 4 * 64, 0.05f);
}

}  // namespace
}  // namespace photon::spot_light_profile_tests
