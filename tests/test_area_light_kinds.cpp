// Area lights beyond a uniform one-sided surface: two-sided emission, textured emission
// and the emission_power normalisation, against their definitions and against the path
// tracer (SPPM on a scene lit by both kinds).
#include <gtest/gtest.h>
#include "math/rng.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"
#include "texture/textures.h"

namespace photon {
namespace {

// A 1 x 1 quad in the plane y = 1 facing down (-y), emitting Le; u along +x, v along +z.
ShapeDescription panel(Color le) {
    ShapeDescription s = test::quad({-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, 0, le);
    return s;
}

std::shared_ptr<const Scene> sceneWith(ShapeDescription light) {
    SceneDescription d;
    d.camera = test::camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40, 8, 8);
    d.materials.push_back(makeDiffuse(Color(0.5f)));
    d.shapes.push_back(std::move(light));
    return Scene::build(std::move(d));
}

TEST(AreaLightKinds, TwoSidedEmitsAlikeOnBothSides) {
    ShapeDescription s = panel(Color(2.0f));
    s.twoSidedEmission = true;
    auto scene = sceneWith(s);
    const Light& light = scene->lights().light(0);
    EXPECT_NEAR(light.power().x, 2.0f * kPi * 1.0f * 2.0f, 1e-5);  // Le pi A sides
    // Radiance seen from above and below.
    SurfaceHit hit;
    ASSERT_TRUE(scene->intersect(Ray{{0, 3, 0}, {0, -1, 0}}, hit));
    EXPECT_EQ(scene->emitted(hit, {0, 1, 0}), Color(2.0f));
    ASSERT_TRUE(scene->intersect(Ray{{0, -3, 0}, {0, 1, 0}}, hit));
    EXPECT_EQ(scene->emitted(hit, {0, -1, 0}), Color(2.0f));
    // Light samples reach points on either side; photons leave half up, half down, each
    // with the whole power.
    EXPECT_TRUE(light.sampleIncident({0, 3, 0}, Vec3(0, -1, 0), {0.3f, 0.6f}).has_value());
    EXPECT_TRUE(light.sampleIncident({0, -3, 0}, Vec3(0, 1, 0), {0.3f, 0.6f}).has_value());
    Rng rng(1, 0, 0, StreamPurpose::Test);
    int up = 0, n = 100000;
    for (int i = 0; i < n; ++i) {
        auto e = light.emitPhoton({rng.uniform(), rng.uniform()}, {rng.uniform(), rng.uniform()});
        ASSERT_TRUE(e);
        EXPECT_EQ(e->flux, light.power());
        EXPECT_GT(dot(e->direction, e->normal), 0.0f);
        up += e->direction.y > 0;
    }
    EXPECT_NEAR(double(up) / n, 0.5, 0.005);
    EXPECT_EQ(light.emissionTriangles(), nullptr);  // not the one-sided lanes' kind
}

// A sphere of radius r and radiance Le seen from distance d: the irradiance on a surface
// facing its centre is pi Le (r/d)^2 (the cap's projected solid angle, pi sin^2 theta_max),
// at any distance, a grazing 1.01 radii or a far 1000. Light samples lie on the near cap, in
// the cone the sphere subtends, with the solid-angle density the MIS weights ask for.
TEST(AreaLightKinds, SphereLightsAreSampledByTheConeTheySubtend) {
    for (float d : {1.01f, 1.5f, 7.0f, 1000.0f}) {
        SCOPED_TRACE("distance " + std::to_string(d));
        ShapeDescription s = test::sphere({0, 0, 0}, 1.0f, 0, Color(3.0f));
        auto scene = sceneWith(s);
        const Light& light = scene->lights().light(0);
        const Vec3 p(0, 0, d), n(0, 0, -1);
        const double sin2Max = 1.0 / (double(d) * d);
        const double oneMinusCos = 1.0 - std::sqrt(1.0 - sin2Max);
        Rng rng(3, 0, 0, StreamPurpose::Test);
        double irradiance = 0;
        const int samples = 20000;
        for (int i = 0; i < samples; ++i) {
            auto ls = light.sampleIncident(p, n, {rng.uniform(), rng.uniform()});
            ASSERT_TRUE(ls);
            irradiance += ls->weight.x * std::max(0.0f, dot(ls->wi, n)) / samples;
            EXPECT_NEAR(ls->pdf, 1.0 / (2 * kPi * oneMinusCos), 2e-3 / (2 * kPi * oneMinusCos));
            const Vec3 y = p + ls->wi * ls->distance;
            EXPECT_NEAR(length(y), 1.0f, 2e-3f * std::max(1.0f, d / 100));  // on the sphere
            EXPECT_GT(dot(y, p - y), -1e-3f * d);                             // on the near cap
            EXPECT_EQ(light.pdfIncidentFrom(p, n, {y, normalize(y), 0}, ls->wi), ls->pdf);
        }
        EXPECT_NEAR(irradiance, kPi * 3.0 * sin2Max, 2e-3 * kPi * 3.0 * sin2Max);
    }
}

// Light samples on a quad light (two triangles) follow the solid angle it subtends, warped by
// the receiver's cosine (warped_light_pieces.h), and are less noisy than samples uniform by
// area, whose weights swing with cos / d^2: at 2 cm 1,000 times less, at 30 cm 29 times
// (before the warp they were uniform by area there). At 3 m, wholly above the receiver and
// farther than WarpedLightPieces::kNear times its radius, it is sampled uniformly by area.
// Each gives Lambert's irradiance, on the panel, with the density the MIS weights ask for.
TEST(AreaLightKinds, QuadLightsAreSampledByTheSolidAngleTheySubtend) {
    auto scene = sceneWith(panel(Color(2.0f)));
    const Light& light = scene->lights().light(0);
    const std::vector<Vec3> corners{{-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f}, {0.5f, 1, 0.5f}, {-0.5f, 1, 0.5f}};
    for (float h : {0.02f, 0.3f, 3.0f}) {
        SCOPED_TRACE("distance " + std::to_string(h));
        const Vec3 p(0.2f, 1 - h, 0.1f), n(0, 1, 0);
        const double expected = test::polygonIrradiance(p, n, corners, 2.0);
        Rng rng(5, 0, 0, StreamPurpose::Test);
        const int samples = 40000;
        double sum = 0, sumSquares = 0, areaSum = 0, areaSquares = 0;
        for (int i = 0; i < samples; ++i) {
            const Vec2 u{rng.uniform(), rng.uniform()};
            auto ls = light.sampleIncident(p, n, u);
            ASSERT_TRUE(ls);
            const double e = ls->weight.x * std::max(0.0f, dot(ls->wi, n));
            sum += e, sumSquares += e * e;
            const Vec3 y = p + ls->wi * ls->distance;
            EXPECT_NEAR(y.y, 1.0f, 1e-4f);
            EXPECT_LE(std::abs(y.x), 0.5f + 1e-4f);
            EXPECT_LE(std::abs(y.z), 0.5f + 1e-4f);
            // The density a ray along the sample is given where it meets the light.
            test::expectRayFindsLightSample(*scene, light, p, n, *ls, i);
            // The same estimate from a point uniform on the panel: Le cos cos' A / d^2.
            const Vec3 q(-0.5f + u.x, 1, -0.5f + u.y), d = q - p;
            const double d2 = lengthSquared(d), c = d.y / std::sqrt(d2);
            const double a = 2.0 * c * c / d2;
            areaSum += a, areaSquares += a * a;
        }
        const double mean = sum / samples, areaMean = areaSum / samples;
        EXPECT_NEAR(mean, expected, 0.01 * expected);
        EXPECT_NEAR(areaMean, expected, 0.05 * expected);
        const double variance = sumSquares / samples - mean * mean;
        const double areaVariance = areaSquares / samples - areaMean * areaMean;
        std::printf("h %.2f: irradiance %.5f (Lambert %.5f); variance of light samples %.5g, of area samples %.5g\n", h, mean,
                    expected, variance, areaVariance);
        if (h < 1) EXPECT_LT(variance, (h < 0.1f ? 0.01 : 0.1) * areaVariance);
    }
}

TEST(AreaLightKinds, TexturedEmissionFollowsTheTexture) {
    ShapeDescription s = panel(Color(3.0f));
    // Cells of a 2 x 1 checkerboard in u: x < 0 even (black), x > 0 odd.
    s.emissionTexture = makeCheckerboardTexture(Color(0.0f), Color(1.0f, 0.5f, 0.25f), UvMapping{{2, 1}, {0, 0}});
    auto scene = sceneWith(s);
    const Light& light = scene->lights().light(0);
    // Mean emission 3 x (0.5, 0.25, 0.125) over the unit area, one side.
    EXPECT_NEAR(light.power().x, 1.5f * kPi, 1e-3);
    EXPECT_NEAR(light.power().z, 0.375f * kPi, 1e-3);
    SurfaceHit hit;
    ASSERT_TRUE(scene->intersect(Ray{{-0.25f, -3, 0}, {0, 1, 0}}, hit));  // u = 0.25: even cell
    EXPECT_EQ(scene->emitted(hit, {0, -1, 0}), Color(0.0f));
    ASSERT_TRUE(scene->intersect(Ray{{0.25f, -3, 0}, {0, 1, 0}}, hit));  // u = 0.75: odd cell
    EXPECT_VEC3_NEAR(scene->emitted(hit, {0, -1, 0}), Color(3.0f, 1.5f, 0.75f), 1e-6);
    // Photons only from the odd half, and their mean flux is the power.
    Rng rng(2, 0, 0, StreamPurpose::Test);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        auto e = light.emitPhoton({rng.uniform(), rng.uniform()}, {rng.uniform(), rng.uniform()});
        ASSERT_TRUE(e);
        if (e->flux.x > 0) EXPECT_GT(e->origin.x, -1e-4f);
        sum += e->flux.x;
    }
    EXPECT_NEAR(sum / n, light.power().x, 0.01 * light.power().x);
}

// SPPM against the path tracer with a two-sided, textured light hanging in the Cornell box
// (lowered from the ceiling: in a gap narrower than the gather radius, SPPM would blur the
// bright light trapped above the panel onto the panel's face).
TEST(AreaLightKinds, SppmAgreesWithThePathTracer) {
    SceneDescription d = test::cornellBoxWith(makeDiffuse(Color(0.6f)), 32);
    for (ShapeDescription& s : d.shapes) {
        if (isBlack(s.emission)) continue;
        s.emissionTexture = makeCheckerboardTexture(Color(0.2f), Color(1.0f), UvMapping{{4, 4}, {0, 0}});
        s.twoSidedEmission = true;
        for (Vec3& p : s.mesh.positions) p.y -= 0.4f;
    }
    test::PathAndSppmMeans m = test::renderPathAndSppm(d, 1024, 128, 100000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.sppm[c], m.path[c], 0.02f * m.path[c]) << "channel " << c;
    std::printf("  path %.5f %.5f %.5f  sppm %.5f %.5f %.5f\n", m.path.x, m.path.y, m.path.z, m.sppm.x, m.sppm.y, m.sppm.z);
}

// An invisible emitter (pbrt-v4's area light of alpha 0) lights as the visible one does, by
// light samples alone, and no ray meets it: over a floor, seen from above through the light,
// the floor around it is as bright as under the visible light (the path tracer and SPPM),
// and the floor under it shows where the visible light hides it.
TEST(AreaLightKinds, AnInvisibleEmitterLightsAsTheVisibleOneAndIsNotSeen) {
    auto render = [](bool invisible, IntegratorKind integrator) {
        SceneDescription d;
        d.camera = test::camera({0, 3, 0}, {0, 0, 0}, {0, 0, -1}, 60, 16, 16);
        // The light black, as an invisible one is: the visible one's reflection of the floor
        // would add 2% to it.
        d.materials = {makeDiffuse(Color(0.5f)), makeDiffuse(Color(0.0f))};
        d.shapes.push_back(test::quad({-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, 0));  // the floor, facing up
        ShapeDescription light = panel(Color(4.0f));
        light.material = 1;
        light.invisible = invisible;
        d.shapes.push_back(light);
        d.render.integrator = integrator;
        d.render.passes = integrator == IntegratorKind::Path ? 256 : 64;
        d.render.photonsPerPass = 20000;
        return test::renderImage(std::move(d));
    };
    const Image visible = render(false, IntegratorKind::Path);
    // The ring of pixels around the light's square (the centre 8 x 8) sees the floor alone.
    auto ring = [](const Image& image) {
        return (test::meanOver(image, 0, 0, 16, 4) + test::meanOver(image, 0, 12, 16, 16) +
                test::meanOver(image, 0, 4, 4, 12) + test::meanOver(image, 12, 4, 16, 12)) * 0.25f;
    };
    const Color around = ring(visible);
    for (IntegratorKind integrator : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        const Image invisible = render(true, integrator);
        const Color aroundInvisible = ring(invisible);
        std::printf("  floor around the light: visible %.4f, invisible (%s) %.4f\n", around.x,
                    integrator == IntegratorKind::Path ? "path" : "sppm", aroundInvisible.x);
        EXPECT_NEAR(aroundInvisible.x, around.x, 0.02f * around.x);
        // Under the light: its unlit back where it is seen, the floor it lights where it is not.
        EXPECT_LT(test::meanOver(visible, 6, 6, 10, 10).x, 0.01f * around.x);
        EXPECT_GT(test::meanOver(invisible, 6, 6, 10, 10).x, 2.0f * around.x);
    }
}

TEST(AreaLightKinds, SceneJsonEmissionFields) {
    using namespace test;
    Json doc = fullScene();
    Json& lamp = doc["shapes"][5];  // a 0.5 x 0.5 quad
    lamp["emission"] = Json::parse(R"({"type": "checkerboard", "even": [1, 1, 1], "odd": [3, 3, 3]})");
    lamp["two_sided"] = true;
    lamp["emission_power"] = 10;
    SceneDescription s = load(doc);
    const ShapeDescription& shape = s.shapes[5];
    EXPECT_TRUE(shape.twoSidedEmission);
    ASSERT_TRUE(shape.emissionTexture);
    // P = Y(mean) pi A sides = 10 W with A = 0.25, two sides.
    EXPECT_NEAR(luminance(shape.meanEmission()) * kPi * 0.25f * 2, 10.0f, 1e-3);
    doc["shapes"][5]["emission"] = Json::parse("[2, 2, 2]");
    doc["shapes"][5].erase("emission_power");
    doc["shapes"][5]["emission_scale"] = 4;
    EXPECT_EQ(load(doc).shapes[5].emission, Color(8.0f));
    expectError([](Json& d) { d["shapes"][0]["emission_power"] = 5; }, "shapes[0].emission_power",
                "needs an emission that is not black on a shape with area");
    expectError([](Json& d) { d["shapes"][5]["emission"] = Json::parse("[-1, 0, 0]"); }, "shapes[5].emission[0]",
                "must be >= 0");
    doc["shapes"][5]["invisible"] = true;
    EXPECT_TRUE(load(doc).shapes[5].invisible);
    expectError([](Json& d) { d["shapes"][0]["invisible"] = true; }, "shapes[0].invisible",
                "only a shape that emits can be invisible");
    expectError(
        [](Json& d) {
            d["shapes"][5]["invisible"] = true;
            d["shapes"][5]["alpha"] = 0.5;
        },
        "shapes[5].alpha", "an emissive shape cannot have an alpha below 1");
}

}  // namespace
}  // namespace photon
