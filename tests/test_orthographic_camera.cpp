// The orthographic camera: parallel rays, a view of fixed size whatever the distance, SPPM's
// radii from the pixel's size rather than its angle, the scene format, and pbrt's and
// glTF's orthographic cameras imported onto it.
#include <gtest/gtest.h>
#include <cmath>
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon {
namespace {

// Looking down -z at an emitter of radiance 1 on [-1, 1]^2 at depth `z`, through a view
// 4 units high at 16 x 16 (a quarter unit a pixel): exactly the middle 8 x 8 pixels see it,
// at any depth.
SceneDescription squareAt(float z) {
    SceneDescription d;
    d.camera = test::orthographicCamera({0, 0, 2}, {0, 0, 0}, 4, 16, 16);
    d.materials = {makeDiffuse(Color(0.0f))};
    d.materialNames = {"black"};
    d.shapes = {test::quad({-1, -1, z}, {2, 0, 0}, {0, 2, 0}, 0, Color(1.0f))};
    d.render.integrator = IntegratorKind::Path;
    d.render.passes = 4;
    return d;
}

TEST(OrthographicCamera, SeesTheSameSquareAtAnyDistance) {
    for (float z : {-1.0f, -30.0f}) {
        const Image image = test::renderImage(squareAt(z));
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const bool inside = x >= 4 && x < 12 && y >= 4 && y < 12;
                ASSERT_EQ(test::meanOver(image, x, y, x + 1, y + 1).x, inside ? 1.0f : 0.0f) << x << ", " << y << ", z " << z;
            }
    }
}

// A diffuse plane (rho 0.5) under a point light 1 above it, seen straight down through a
// view 1 unit high: SPPM's radiance at the middle is rho / pi I / h^2 within 3% (its auto
// radius sized from the pixel's side, 1/16, not from an angle).
TEST(OrthographicCamera, SppmOnAPlaneUnderAPointLight) {
    SceneDescription d = test::pointLightPlane(0.5f, 1.0f, 1.0f, 16, 2.0f);
    d.camera.projection = CameraProjection::Orthographic;
    d.camera.viewHeight = 1;
    d.render.integrator = IntegratorKind::Sppm;
    d.render.passes = 64;
    d.render.photonsPerPass = 50000;
    // Over the middle 4 x 4 pixels (0.25 units across) cos^4 theta averages 0.990.
    const Color c = test::meanOver(test::renderImage(std::move(d)), 6, 6, 10, 10);
    const float expected = 0.5f / kPi * 0.990f;
    EXPECT_NEAR(c.x, expected, 0.03f * expected);
}

using test::expectError;
using test::load;

TEST(OrthographicCameraScene, FieldsAndErrors) {
    Json doc = test::fullScene();
    doc["camera"] = {{"type", "orthographic"}, {"position", {0, 1, 5}}, {"look_at", {0, 1, 0}}, {"view_height", 3}};
    const SceneDescription d = load(doc);
    EXPECT_EQ(d.camera.projection, CameraProjection::Orthographic);
    EXPECT_EQ(d.camera.viewHeight, 3.0f);
    auto ortho = [](Json& doc) {
        doc["camera"] = {{"type", "orthographic"}, {"position", {0, 1, 5}}, {"look_at", {0, 1, 0}}, {"view_height", 3}};
    };
    expectError(
        [&](Json& doc) {
            ortho(doc);
            doc["camera"]["fov"] = 30;
        },
        "camera.fov", "is not used by an orthographic camera (its view is \"view_height\" high)");
    expectError(
        [&](Json& doc) {
            ortho(doc);
            doc["camera"]["aperture_radius"] = 0.1;
        },
        "camera.aperture_radius", "must be 0 for an orthographic camera (it has no lens)");
    expectError(
        [&](Json& doc) {
            ortho(doc);
            doc["camera"].erase("view_height");
        },
        "camera.view_height", "missing required field");
    expectError([](Json& doc) { doc["camera"]["view_height"] = 2; }, "camera.view_height",
                "is only used by an orthographic camera");
}

}  // namespace
}  // namespace photon
