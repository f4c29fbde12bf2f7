// The spherical camera: every direction around the camera on one image, laid out as
// pbrt-v4's SphericalCamera lays it (equal-area square or equirectangular); the scene
// format; pbrt's spherical camera imported onto it, against pbrt's own formulas; and the
// integrators through it, held to a furnace's analytic radiance.
#include <gtest/gtest.h>
#include <cmath>
#include <photon/render.h>
#include "camera/camera.h"
#include "import/pbrt/pbrt_import.h"
#include "math/equal_area.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon {
namespace {

using test::expectError;
using test::load;

CameraDescription sphericalCamera(CameraSphericalMapping mapping, int width, int height) {
    CameraDescription c;
    c.position = {1, 2, 3};
    c.lookAt = {1, 2, 2};  // forward -z, up +y, right +x
    c.up = {0, 1, 0};
    c.projection = CameraProjection::Spherical;
    c.mapping = mapping;
    c.width = width, c.height = height;
    return c;
}

Vec3 directionAt(const Camera& camera, float x, float y) {
    const Ray r = camera.generateRay(x, y, {0.5f, 0.5f});
    EXPECT_VEC3_NEAR(r.o, Vec3(1, 2, 3), 1e-6f);
    return r.d;
}

// Equirectangular: the centre looks forward, the top row up, the bottom row down, a
// quarter of the width to the right looks right, the left and right edges back.
TEST(SphericalCamera, EquirectangularLayout) {
    const Camera c(sphericalCamera(CameraSphericalMapping::Equirectangular, 64, 32));
    EXPECT_VEC3_NEAR(directionAt(c, 32, 16), Vec3(0, 0, -1), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 48, 16), Vec3(1, 0, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 16, 16), Vec3(-1, 0, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 0, 16), Vec3(0, 0, 1), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 10, 0), Vec3(0, 1, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 10, 32), Vec3(0, -1, 0), 1e-5f);
    // 45 degrees up, straight ahead.
    EXPECT_VEC3_NEAR(directionAt(c, 32, 8), normalize(Vec3(0, 1, -1)), 1e-5f);
}

// Equal-area: the square's centre looks up, its corners down, the middles of its left,
// right, top and bottom edges forward, back, right and left; and equal areas of the image
// see equal solid angles: its pixels' directions, counted by octant, fall 1/8 in each.
TEST(SphericalCamera, EqualAreaLayoutAndSolidAngles) {
    const Camera c(sphericalCamera(CameraSphericalMapping::EqualArea, 64, 64));
    EXPECT_VEC3_NEAR(directionAt(c, 32, 32), Vec3(0, 1, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 0, 0), Vec3(0, -1, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 64, 64), Vec3(0, -1, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 0, 32), Vec3(0, 0, -1), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 64, 32), Vec3(0, 0, 1), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 32, 0), Vec3(1, 0, 0), 1e-5f);
    EXPECT_VEC3_NEAR(directionAt(c, 32, 64), Vec3(-1, 0, 0), 1e-5f);
    // (The 128 pixel centres on the square's diamond look exactly along the horizon and
    // belong to no octant.)
    int octants[8] = {}, onTheHorizon = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Vec3 d = directionAt(c, x + 0.5f, y + 0.5f);
            if (std::abs(d.y) < 1e-6f) {
                ++onTheHorizon;
                continue;
            }
            ++octants[(d.x > 0) | (d.y > 0) << 1 | (d.z > 0) << 2];
        }
    EXPECT_EQ(onTheHorizon, 128);
    for (int o = 0; o < 8; ++o) EXPECT_EQ(octants[o], (64 * 64 - 128) / 8) << "octant " << o;
    // A filter's sample past the edge folds back across it (pbrt's WrapEqualAreaSquare).
    EXPECT_VEC3_NEAR(directionAt(c, -0.5f, 10), directionAt(c, 0.5f, 54), 1e-5f);
}

// Inside a closed sphere of albedo 0.5 emitting 1 everywhere, every direction sees
// 1 / (1 - 0.5) = 2: through either layout, with the path tracer and with SPPM (whose auto
// radius reads the spherical pixel's angle).
TEST(SphericalCamera, FurnaceSeesTheSameRadianceEverywhere) {
    for (CameraSphericalMapping mapping : {CameraSphericalMapping::EqualArea, CameraSphericalMapping::Equirectangular})
        for (IntegratorKind integrator : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            SceneDescription d = test::furnace(0.5f, 1.0f, 16);
            d.camera = sphericalCamera(mapping, 16, mapping == CameraSphericalMapping::EqualArea ? 16 : 8);
            d.camera.position = {0, 0, 0}, d.camera.lookAt = {0, 0, 1};
            d.render.integrator = integrator;
            d.render.maxDepth = 200;
            d.render.passes = integrator == IntegratorKind::Path ? 256 : 32;
            d.render.photonsPerPass = 50000;
            const int w = d.camera.width, h = d.camera.height;
            const Image image = test::renderImage(std::move(d));
            const Color mean = test::meanOver(image, 0, 0, w, h);
            for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean[ch], 2.0f, 0.04f);
            // The top and bottom halves (up and down, or the square's middle and rim) alike.
            EXPECT_NEAR(test::meanOver(image, 0, 0, w, h / 2).y, 2.0f, 0.1f);
            EXPECT_NEAR(test::meanOver(image, 0, h / 2, w, h).y, 2.0f, 0.1f);
        }
}

TEST(SphericalCameraScene, FieldsAndErrors) {
    Json doc = test::fullScene();
    doc["camera"] = {{"type", "spherical"}, {"position", {0, 1, 5}}, {"look_at", {0, 1, 0}}};
    EXPECT_EQ(load(doc).camera.projection, CameraProjection::Spherical);
    EXPECT_EQ(load(doc).camera.mapping, CameraSphericalMapping::EqualArea);
    doc["camera"]["mapping"] = "equirectangular";
    EXPECT_EQ(load(doc).camera.mapping, CameraSphericalMapping::Equirectangular);
    auto spherical = [](Json& doc) {
        doc["camera"] = {{"type", "spherical"}, {"position", {0, 1, 5}}, {"look_at", {0, 1, 0}}};
    };
    expectError(
        [&](Json& doc) {
            spherical(doc);
            doc["camera"]["fov"] = 30;
        },
        "camera.fov", "is not used by a spherical camera (it sees every direction)");
    expectError(
        [&](Json& doc) {
            spherical(doc);
            doc["camera"]["aperture_radius"] = 0.1;
        },
        "camera.aperture_radius", "must be 0 for a spherical camera (it has no lens)");
    expectError(
        [&](Json& doc) {
            spherical(doc);
            doc["camera"]["mapping"] = "cube";
        },
        "camera.mapping", "unknown mapping \"cube\" (expected one of equal_area, equirectangular)");
}

// pbrt-v4's SphericalCamera::GenerateRay, written out from its definition: (u, v) the film
// position over the resolution; equirectangular: theta = pi v, phi = 2 pi u, the direction
// (sin theta cos phi, sin theta sin phi, cos theta); equal-area: Clarberg's square; then y
// and z swapped; then from camera space to the world. pbrt's LookAt puts camera x at
// up x dir, y at dir x x, z at dir.
Vec3 pbrtSphericalRay(bool equirectangular, Vec2 uv, Vec3 pos, Vec3 look, Vec3 up, Vec3 mirror) {
    Vec3 d;
    if (equirectangular) {
        const float theta = kPi * uv.y, phi = 2 * kPi * uv.x;
        d = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    } else {
        d = equalAreaSquareToSphere(uv);
    }
    std::swap(d.y, d.z);
    d = d * mirror;  // a Scale before LookAt mirrors camera space
    const Vec3 dir = normalize(look - pos);
    const Vec3 x = normalize(cross(normalize(up), dir));
    const Vec3 y = cross(dir, x);
    return normalize(x * d.x + y * d.y + dir * d.z);
}

// Imported from pbrt: the same rays as pbrt's for both mappings, with and without a mirror
// in the camera's transform (pbrt files often start with Scale -1 1 1).
TEST(SphericalCameraImport, RaysAreThoseOfPbrt) {
    const test::fs::path dir = test::fs::temp_directory_path() / ("photon-spherical-" + std::to_string(::getpid()));
    for (const bool equirectangular : {false, true})
        for (const bool mirrored : {false, true}) {
            const std::string text = std::string(mirrored ? "Scale -1 1 1\n" : "") +
                                     "LookAt 1 2 3  4 2 -1  0 1 0\n"
                                     "Camera \"spherical\" \"string mapping\" \"" +
                                     (equirectangular ? "equirectangular" : "equalarea") +
                                     "\"\n"
                                     "Film \"rgb\" \"integer xresolution\" [32] \"integer yresolution\" [" +
                                     (equirectangular ? "16" : "32") +
                                     "]\n"
                                     "WorldBegin\n"
                                     "LightSource \"point\" \"rgb I\" [1 1 1]\n"
                                     "Shape \"sphere\"\n";
            test::writeText(dir / "scene.pbrt", text);
            const SceneDescription d = loadImportedScene(importPbrt(dir / "scene.pbrt"), dir);
            ASSERT_EQ(d.camera.projection, CameraProjection::Spherical);
            const Camera camera(d.camera);
            const float w = 32, h = equirectangular ? 16 : 32;
            for (const Vec2 uv : {Vec2{0.5f, 0.5f}, Vec2{0.1f, 0.3f}, Vec2{0.8f, 0.7f}, Vec2{0.3f, 0.9f}, Vec2{0.6f, 0.05f}}) {
                const Vec3 expected = pbrtSphericalRay(equirectangular, uv, {1, 2, 3}, {4, 2, -1}, {0, 1, 0},
                                                       mirrored ? Vec3(-1, 1, 1) : Vec3(1, 1, 1));
                const Ray r = camera.generateRay(uv.x * w, uv.y * h, {0.5f, 0.5f});
                SCOPED_TRACE(testing::Message() << "uv " << uv.x << ", " << uv.y
                                                << (equirectangular ? " equirectangular" : " equal-area")
                                                << (mirrored ? " mirrored" : ""));
                EXPECT_VEC3_NEAR(r.d, expected, 1e-4f);
                EXPECT_VEC3_NEAR(r.o, Vec3(1, 2, 3), 1e-4f);
            }
        }
    std::error_code ec;
    test::fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace photon
