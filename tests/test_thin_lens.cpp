// Depth of field of the thin-lens camera: a small glowing sphere on the plane in focus is
// sharp, one twice as far is blurred into the circle of confusion the lens predicts.
//
// A ray leaves lens point L (|L| <= aperture A) toward the point F on the plane in focus
// (depth f) that its pixel looks at. It meets a point P at depth d when
// F = P f/d + L (1 - f/d): the point spreads over a disc of radius A |1 - f/d| on the plane
// in focus, which the perspective projection maps linearly to a disc of
// A |1 - f/d| / f * H / (2 tan(fov/2)) pixels, uniformly filled (lens points are uniform).
// A uniform disc of radius R has mean squared distance R^2 / 2 from its centre; the sphere's
// own disc and the pixel's box add their variances to it.
#include <gtest/gtest.h>
#include <photon/render.h>
#include "integrators/integrator.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr int kWidth = 96, kHeight = 48;
constexpr float kFovDegrees = 30, kAperture = 0.3f, kFocus = 2;
// Samples (film and lens points) per pixel. Each sphere covers ~1.4 square pixels, so about
// 5800 samples land on each: enough for the statistics below to be tight (see each check).
constexpr int kSamples = 4096;
// Pixels per unit of lateral offset over depth (the perspective projection is linear in it).
const float kPixelsPerTan = kHeight / (2 * std::tan(kFovDegrees * kPi / 360));

struct Blob {
    double cx = 0, cy = 0, meanSquaredRadius = 0, total = 0;
};

// The luminance-weighted centre and mean squared distance from it over columns [x0, x1).
Blob measure(const Image& image, int x0, int x1) {
    Blob b;
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x) {
            double w = luminance(image.at(x, y));
            b.total += w;
            b.cx += w * (x + 0.5);
            b.cy += w * (y + 0.5);
        }
    b.cx /= b.total;
    b.cy /= b.total;
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x) {
            double dx = x + 0.5 - b.cx, dy = y + 0.5 - b.cy;
            b.meanSquaredRadius += luminance(image.at(x, y)) * (dx * dx + dy * dy);
        }
    b.meanSquaredRadius /= b.total;
    return b;
}

TEST(ThinLens, ThePlaneInFocusIsSharpAndATwiceAsFarPointBlursIntoThePredictedCircle) {
    // Two spheres of the same angular radius (0.0075 rad): one in focus on the left, one at
    // twice the focus distance on the right. Nothing else in the scene: black around them.
    const float nearDepth = kFocus, farDepth = 2 * kFocus, angle = 0.0075f;
    SceneDescription d;
    d.camera = test::camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, kFovDegrees, kWidth, kHeight);
    d.camera.apertureRadius = kAperture;
    d.camera.focusDistance = kFocus;
    d.materials = {makeDiffuse(Color(0.0f))};
    d.materialNames = {"black"};
    d.shapes = {test::sphere({-0.35f, 0, -nearDepth}, angle * nearDepth, 0, Color(1.0f)),
                test::sphere({0.7f, 0, -farDepth}, angle * farDepth, 0, Color(1.0f))};
    d.render.integrator = IntegratorKind::Path;
    d.render.passes = kSamples;
    Renderer renderer(Scene::build(std::move(d)));
    CancelToken cancel;
    ASSERT_EQ(renderer.run(cancel), RenderOutcome::Completed);
    Image image = renderer.snapshot();

    // The sphere's own disc (uniformly bright: radius^2 / 2) and the pixel box (1/12 per
    // axis, Sheppard's correction): 0.39 square pixels. How a disc this small falls on the
    // pixel grid moves its measured spread between 0 and about that, so in focus means
    // within a pixel; the blurred disc's 22 square pixels barely notice the difference.
    const double sphereRadius = angle * kPixelsPerTan;
    const double sharp = sphereRadius * sphereRadius / 2 + 2.0 / 12;
    Blob inFocus = measure(image, 0, kWidth / 2), blurred = measure(image, kWidth / 2, kWidth);
    EXPECT_LT(inFocus.meanSquaredRadius, 1.0);

    const double circle = kAperture * std::abs(1 - kFocus / farDepth) / kFocus * kPixelsPerTan;  // 6.7 pixels
    // r^2 over a uniform disc is uniform on [0, R^2]: its mean from ~5800 samples is good to
    // 0.8% (standard error), the radius to 0.4%; 4% is ten of those.
    const double measured = std::sqrt(2 * (blurred.meanSquaredRadius - sharp));
    EXPECT_NEAR(measured, circle, 0.04 * circle);
    // Both sit where their centres project, the lens moving neither.
    EXPECT_NEAR(inFocus.cx, kWidth / 2.0 - 0.35 / nearDepth * kPixelsPerTan, 0.2);
    EXPECT_NEAR(blurred.cx, kWidth / 2.0 + 0.7 / farDepth * kPixelsPerTan, 0.2);
    EXPECT_NEAR(blurred.cy, kHeight / 2.0, 0.2);
    // Spreading keeps the light: both spheres send the same power into the lens. Each total
    // counts samples that hit (1 / kSamples each): four standard errors of the difference.
    EXPECT_NEAR(blurred.total, inFocus.total, 4 * std::sqrt((blurred.total + inFocus.total) / kSamples));
}

}  // namespace
}  // namespace photon
