// Absorbing media (docs/scene-format.md#media): Beer-Lambert along camera paths and photon
// paths, the medium a path is in changed where it crosses a boundary, the scene format.
#include <gtest/gtest.h>
#include "media/diffusion_dipole.h"
#include "math/spectrum_rgb.h"
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "import/pbrt/pbrt_import.h"
#include "materials/material.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon {
namespace {

namespace fs = std::filesystem;

const Color kAbsorption(0.5f, 1.0f, 2.0f);

// The camera looks down -z through a slab 1 thick (z in [-0.5, 0.5]) at a white emitter of
// radiance 1. The slab's faces are a dielectric of index 1 (no surface: every ray goes
// through unbent) bounding a medium of absorption (0.5, 1, 2): the pixels at the middle of
// a narrow view see exp(-absorption) = (0.607, 0.368, 0.135), to the error of their rays'
// slant (at most 1 / cos 0.9 degrees - 1 = 0.01%).
SceneDescription slabBeforeAnEmitter(IntegratorKind kind, bool inside) {
    SceneDescription d;
    d.camera = test::camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 6, 8, 8);
    d.materials = {makeDiffuse(Color(0.0f)), makeDielectric(1.0f)};
    d.materialNames = {"black", "boundary"};
    d.media = {{"absorbs", kAbsorption}};
    d.shapes = {test::quad({-5, -5, -2}, {10, 0, 0}, {0, 10, 0}, 0, Color(1.0f))};
    for (ShapeDescription& face : test::boxFaces({-2, -2, -0.5f}, {2, 2, 0.5f}, 1)) {
        // The medium inside the box, or the same faces turned inside out with the medium
        // outside them: the same image.
        if (inside) {
            face.insideMedium = 0;
        } else {
            face.flipNormals = true;
            face.outsideMedium = 0;
        }
        d.shapes.push_back(face);
    }
    d.render.integrator = kind;
    d.render.passes = 4;
    d.render.photonsPerPass = 1000;
    return d;
}

TEST(AbsorbingMedium, SlabTransmitsExpOfMinusAbsorptionTimesThickness) {
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm})
        for (bool inside : {true, false}) {
            const Image image = test::renderImage(slabBeforeAnEmitter(kind, inside));
            const Color seen = test::meanOver(image, 3, 3, 5, 5);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(seen[c], std::exp(-kAbsorption[c]), 2e-3f)
                    << "integrator " << int(kind) << ", medium " << (inside ? "inside" : "outside") << ", channel " << c;
        }
}

// The Cornell box with a glass sphere (index 1.5, radius 0.3) whose inside absorbs
// (0.3, 1.5, 4) per unit: photons (SPPM) and camera paths (the path tracer) carry the
// medium through the sphere and agree, in the image and in its lower half (the sphere, its
// caustic and shadow), within 2.5% per channel; without the medium the lower half is
// brighter in green and blue by far more than that.
TEST(AbsorbingMedium, SppmAgreesWithThePathTracerThroughATintedGlassSphere) {
    auto scene = [](bool absorbs) {
        SceneDescription d = test::cornellBoxWith(makeDielectric(1.5f), 32, true);
        if (absorbs) {
            d.media = {{"tint", Color(0.3f, 1.5f, 4.0f)}};
            d.shapes.back().insideMedium = 0;
        }
        return d;
    };
    auto means = [](SceneDescription d, IntegratorKind kind, int passes) {
        d.render.integrator = kind;
        d.render.passes = passes;
        d.render.photonsPerPass = 50000;
        d.render.adaptivePhotons = false;
        const Image image = test::renderImage(std::move(d));
        return std::pair{test::meanOver(image, 0, 0, 32, 32), test::meanOver(image, 0, 16, 32, 32)};
    };
    const auto [pathAll, pathLow] = means(scene(true), IntegratorKind::Path, 1024);
    const auto [sppmAll, sppmLow] = means(scene(true), IntegratorKind::Sppm, 256);
    const auto [clearAll, clearLow] = means(scene(false), IntegratorKind::Path, 256);
    std::printf("  lower half: path %.4f %.4f %.4f  sppm %.4f %.4f %.4f  clear glass %.4f %.4f %.4f\n", pathLow.x,
                pathLow.y, pathLow.z, sppmLow.x, sppmLow.y, sppmLow.z, clearLow.x, clearLow.y, clearLow.z);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(sppmAll[c], pathAll[c], 0.025f * pathAll[c]) << "channel " << c;
        EXPECT_NEAR(sppmLow[c], pathLow[c], 0.025f * pathLow[c]) << "channel " << c;
    }
    EXPECT_GT(clearLow.z, 1.1f * pathLow.z);
}

// The same slab as a pbrt-v4 file writes it: an "interface" box bounding a homogeneous
// medium of sigma_a (0.25, 0.5, 1) times scale 2 and sigma_s 0, imported and rendered: the
// middle pixels see exp(-sigma_a scale) of the emitter behind (a box pixel filter, as in
// the test above: pbrt's default Gaussian weights its samples, which adds noise).
TEST(AbsorbingMedium, PbrtSlabImportsAndRendersToBeerLambert) {
    const fs::path dir = fs::temp_directory_path() / ("photon-media-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "slab.pbrt") << R"(LookAt 0 0 3  0 0 0  0 1 0
Camera "perspective" "float fov" [6]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Shape "trianglemesh" "point3 P" [-5 -5 -2  5 -5 -2  5 5 -2  -5 5 -2] "integer indices" [0 1 2 0 2 3]
AttributeEnd
MakeNamedMedium "absorbs" "string type" "homogeneous" "rgb sigma_a" [0.25 0.5 1] "rgb sigma_s" [0 0 0]
  "float scale" [2]
AttributeBegin
  MediumInterface "absorbs" ""
  Material "interface"
  Translate 0 0 -0.5
  Shape "trianglemesh" "point3 P" [-2 -2 0  2 -2 0  2 2 0  -2 2 0  -2 -2 1  2 -2 1  2 2 1  -2 2 1]
    "integer indices" [0 2 1 0 3 2  4 5 6 4 6 7  0 1 5 0 5 4  2 3 7 2 7 6  1 2 6 1 6 5  0 4 7 0 7 3]
AttributeEnd
)";
    SceneDescription d = loadImportedScene(importPbrt(dir / "slab.pbrt"), dir);
    d.render.passes = 4;
    d.render.photonsPerPass = 1000;
    ASSERT_EQ(d.media.size(), 1u);
    const Color seen = test::meanOver(test::renderImage(std::move(d)), 3, 3, 5, 5);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], std::exp(-kAbsorption[c]), 2e-3f) << "channel " << c;
    fs::remove_all(dir);
}

// A grey plane (albedo 0.5) at y = 0 under a point light of intensity 1 at height 2, seen
// straight down from height 0.4 through a narrow view, and a box of the absorbing medium
// spanning y in [lo, hi] over the whole plane, bounded by faces of index 1 (pbrt-v4's
// "interface": no surface). Where the light and the camera are in the box is set by the
// caller. The middle pixels see rho / pi I / 4 times the transmittance along the light's
// way and the camera's.
SceneDescription planeUnderAPointLightAndABox(IntegratorKind kind, float lo, float hi) {
    SceneDescription d;
    d.camera = test::camera({0, 0.4f, 0}, {0, 0, 0}, {0, 0, -1}, 5, 8, 8);
    d.materials = {makeDiffuse(Color(0.5f)), makeDielectric(1.0f)};
    d.materialNames = {"grey", "boundary"};
    d.media = {{"absorbs", kAbsorption}};
    d.shapes = {test::quad({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, 0)};
    for (ShapeDescription& face : test::boxFaces({-5, lo, -5}, {5, hi, 5}, 1)) {
        face.insideMedium = 0;
        d.shapes.push_back(face);
    }
    LightDescription light;
    light.kind = LightDescription::Kind::Point;
    light.position = {0, 2, 0};
    light.intensity = Color(1.0f);
    d.lights = {light};
    d.render.integrator = kind;
    d.render.passes = kind == IntegratorKind::Sppm ? 64 : 16;
    d.render.photonsPerPass = 100000;
    return d;
}

// Shadow rays cross the box's faces (no surface) taking on the medium's absorption, and so
// do photons: a point light behind a slab 1 thick lights the plane with exp(-absorption),
// which a shadow ray blocked at the first face would leave black in the path tracer. Then
// the light inside the box (0.5 from its floor; its photons start in the medium), and the
// camera inside it (0.2 above the plane, 0.8 below the light): exp(-0.5 absorption) and
// exp(-absorption). The path tracer within 1%, SPPM within 3% (its radius's bias). A light
// or a camera inside the box whose medium the scene does not say is in it all the same
// (Scene::placeLightsInMedia): before, the light's photons started in no medium, and SPPM's
// plane read exp(0.5 absorption) of the answer, 1.28 to 2.72 times it by channel; the
// camera's rays crossed no medium to the plane.
TEST(AbsorbingMedium, ShadowRaysCameraAndLightsInMedia) {
    struct Case {
        const char* what;
        float lo, hi, depth;
        bool lightInside, cameraInside, mediumSaid = true;
    };
    for (const Case& c : {Case{"slab between", 0.5f, 1.5f, 1.0f, false, false},
                          Case{"light inside", 1.5f, 2.5f, 0.5f, true, false},
                          Case{"light inside, its medium unsaid", 1.5f, 2.5f, 0.5f, true, false, false},
                          Case{"camera inside", 0.2f, 1.0f, 1.0f, false, true},
                          Case{"camera inside, its medium unsaid", 0.2f, 1.0f, 1.0f, false, true, false}})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            SceneDescription d = planeUnderAPointLightAndABox(kind, c.lo, c.hi);
            if (c.lightInside && c.mediumSaid) d.lights[0].medium = 0;
            if (c.cameraInside && c.mediumSaid) d.camera.medium = 0;
            const Color seen = test::meanOver(test::renderImage(d), 2, 2, 6, 6);
            for (int ch = 0; ch < 3; ++ch) {
                const float expected = 0.5f / kPi * 0.25f * std::exp(-kAbsorption[ch] * c.depth);
                EXPECT_NEAR(seen[ch], expected, (kind == IntegratorKind::Path ? 0.01f : 0.03f) * expected)
                    << c.what << ", integrator " << int(kind) << ", channel " << ch;
            }
        }
}

// A wall under a ceiling light, seen at the height where its shadow rays climb at about 20
// degrees, and a box of nearly clear medium (absorption 1e-4) whose top face is 1 cm under
// the light. A shadow ray crosses the box's faces toward the point it was cast to and stops
// short of the light: the wall's direct light is the same with the box and without it.
// Before, a ray that crossed the top face went on by its old length from the offset origin,
// reached the light, and was blocked: the wall got 58% of its light (the Cornell box with
// fog, docs/sppm.md).
TEST(AbsorbingMedium, ShadowRaysThroughABoundaryUnderALightReachIt) {
    auto wall = [](bool box) {
        SceneDescription d;
        d.camera = test::camera({1.5f, 1.6f, 0}, {-1, 1.6f, 0}, {0, 1, 0}, 10, 8, 8);
        d.materials = {makeDiffuse(Color(0.5f)), makeDielectric(1.0f)};
        d.materialNames = {"grey", "boundary"};
        d.media = {{"clear", Color(1e-4f)}};
        d.shapes = {test::quad({-1, -1, 3}, {0, 0, -6}, {0, 4, 0}, 0),
                    test::quad({-0.25f, 2, -0.25f}, {0.5f, 0, 0}, {0, 0, 0.5f}, 0, Color(10.0f))};
        if (box)
            for (ShapeDescription& face : test::boxFaces({-0.99f, -1, -2}, {2, 1.99f, 2}, 1)) {
                face.insideMedium = 0;
                d.shapes.push_back(face);
            }
        d.render.integrator = IntegratorKind::Path;
        d.render.maxDepth = 1;
        d.render.passes = 16;
        return test::meanOver(test::renderImage(std::move(d)), 0, 0, 8, 8);
    };
    const Color without = wall(false), with = wall(true);
    EXPECT_GT(without.x, 0.01f);
    EXPECT_NEAR(with.x, without.x, 0.005f * without.x);
}

// pbrt-v4's camera and lights take MediumInterface's outside medium where they are declared.
TEST(AbsorbingMedium, PbrtCameraAndLightMedia) {
    const fs::path dir = fs::temp_directory_path() / ("photon-media-cam-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "water.pbrt") << R"(MakeNamedMedium "water" "string type" "homogeneous" "rgb sigma_a" [0.1 0.05 0.01] "rgb sigma_s" [0 0 0]
MediumInterface "" "water"
LookAt 0 1 3  0 0 0  0 1 0
Camera "perspective" "float fov" [30]
WorldBegin
MediumInterface "" "water"
LightSource "point" "point3 from" [0 2 0] "rgb I" [1 1 1]
LightSource "distant" "point3 from" [0 2 0] "point3 to" [0 0 0] "rgb L" [1 1 1]
Shape "trianglemesh" "point3 P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5] "integer indices" [0 2 1 0 3 2]
)";
    const ImportedScene s = importPbrt(dir / "water.pbrt");
    EXPECT_EQ(s.document["camera"]["medium"], "water");
    EXPECT_EQ(s.document["lights"][0]["medium"], "water");
    EXPECT_FALSE(s.document["lights"][1].contains("medium"));
    const SceneDescription d = loadImportedScene(s, dir);
    EXPECT_EQ(d.camera.medium, 0);
    EXPECT_EQ(d.lights[0].medium, 0);
    EXPECT_EQ(d.lights[1].medium, -1);
}

// ---- the scene file ----

using test::expectError;
using test::load;

TEST(MediaScene, MediaAndTheShapesThatBoundThem) {
    Json doc = test::fullScene();
    doc["media"] = {{"wine", {{"absorption", {1, 2, 3}}, {"scale", 0.5}}}, {"water", {{"absorption", {0, 0.1, 0.2}}}}};
    doc["shapes"][3]["medium"] = {{"inside", "wine"}};
    doc["shapes"][0]["medium"] = {{"inside", "water"}, {"outside", "wine"}};
    const SceneDescription d = load(doc);
    ASSERT_EQ(d.media.size(), 2u);
    EXPECT_EQ(d.media[0].name, "wine");
    EXPECT_VEC3_NEAR(d.media[0].absorption, Color(0.5f, 1.0f, 1.5f), 1e-6f);
    EXPECT_EQ(d.shapes[3].insideMedium, 0);
    EXPECT_EQ(d.shapes[3].outsideMedium, -1);
    EXPECT_EQ(d.shapes[0].insideMedium, 1);
    EXPECT_EQ(d.shapes[0].outsideMedium, 0);
    EXPECT_EQ(d.shapes[1].insideMedium, -1);
    EXPECT_FALSE(d.shapes[1].boundsMedium());
    doc["camera"]["medium"] = "water";
    doc["lights"] = {{{"type", "point"}, {"position", {0, 1, 0}}, {"intensity", {1, 1, 1}}, {"medium", "wine"}}};
    const SceneDescription inMedia = load(doc);
    EXPECT_EQ(inMedia.camera.medium, 1);
    EXPECT_EQ(inMedia.lights[0].medium, 0);
}

// A medium given by its look: a reflectance (here a texture) and a mean free path, divided by
// the medium's scale as its coefficients are multiplied; its coefficients those of the
// texture's mean (red, green, blue and white: 0.5 each), its walk one vertex by default.
TEST(MediaScene, AMediumGivenByItsReflectance) {
    Json doc = test::fullScene();
    doc["media"] = {{"skin", {{"reflectance", {{"texture", "textures/wood.png"}}}, {"mean_free_path", {0.1, 0.2, 0.4}},
                              {"scale", 2}, {"boundary_ior", 1.4}}},
                    {"wax", {{"reflectance", {0.5, 0.5, 0.5}}, {"mean_free_path", {1, 1, 1}}, {"subsurface", false}}}};
    doc["shapes"][3]["medium"] = {{"inside", "skin"}};
    const SceneDescription d = load(doc);
    const MediumDescription& skin = d.media[0];
    ASSERT_TRUE(skin.reflectance);
    EXPECT_TRUE(skin.reflectance->reflectance.textured());
    EXPECT_VEC3_NEAR(skin.reflectance->meanFreePath, Color(0.05f, 0.1f, 0.2f), 1e-7f);
    EXPECT_FLOAT_EQ(skin.reflectance->boundaryIor, 1.4f);
    EXPECT_TRUE(skin.subsurface);
    EXPECT_FALSE(d.media[1].subsurface);
    const ScatteringCoefficients c = coefficientsOfReflectance(Color(0.5f), {0.05f, 0.1f, 0.2f}, 1.4);
    EXPECT_VEC3_NEAR(skin.absorption, c.absorption, 1e-4f);
    EXPECT_VEC3_NEAR(skin.scattering, c.scattering, 1e-4f);
    EXPECT_NEAR(skin.absorption.x + skin.scattering.x, 20.0f, 1e-4f);
    // The scene holds the textured medium's palette after the scene's media: (32 + 1)^3.
    const auto scene = Scene::build(d);
    EXPECT_EQ(scene->description().media.size(), 2u + 33u * 33u * 33u);
    EXPECT_EQ(scene->mediumFamily(2), 0);
    EXPECT_EQ(scene->mediumFamily(1), 1);
}

// A density grid: two samples over the box [0, 2] x [0, 1] x [0, 1], moved 1 along x. Its
// samples sit at the centres of the box's halves, x = 1.5 and 2.5 in the world; toward the
// faces the density falls as toward zeros beyond, and outside the box it is zero.
TEST(MediaScene, ADensityGridIsPlacedByItsBoundsAndTransform) {
    Json doc = test::fullScene();
    doc["media"] = {{"smoke",
                     {{"scattering", {1, 1, 1}},
                      {"density",
                       {{"resolution", {2, 1, 1}},
                        {"values", {1, 3}},
                        {"bounds", {{0, 0, 0}, {2, 1, 1}}},
                        {"transform", {{"translate", {1, 0, 0}}}}}}}}};
    const SceneDescription d = load(doc);
    ASSERT_TRUE(d.media[0].density);
    const DensityGrid& grid = *d.media[0].density;
    EXPECT_NEAR(grid.at({1.5f, 0.5f, 0.5f}), 1.0f, 1e-5f);
    EXPECT_NEAR(grid.at({2.0f, 0.5f, 0.5f}), 2.0f, 1e-5f);
    EXPECT_NEAR(grid.at({2.5f, 0.5f, 0.5f}), 3.0f, 1e-5f);
    EXPECT_NEAR(grid.at({1.0f, 0.5f, 0.5f}), 0.5f, 1e-5f);
    EXPECT_EQ(grid.at({0.9f, 0.5f, 0.5f}), 0.0f);
    EXPECT_NEAR(d.media[0].densityLength({0, 0.5f, 0.5f}, {1, 0, 0}, 10), 0.5 * 0.75 + 2 + 0.5 * 2.25, 1e-5);
    EXPECT_TRUE(d.media[0].scatters());

    expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["smoke"]["density"]["values"] = {1, 2, 3}; },
                "media.smoke.density.values", "must hold nx * ny * nz = 2 numbers, not 3");
    expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["smoke"]["density"]["values"] = {1, -2}; },
                "media.smoke.density.values[1]", "must be a finite number >= 0");
    expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["smoke"]["density"]["resolution"] = {2, 1}; },
                "media.smoke.density.resolution", "must be [nx, ny, nz]");
    expectError(
        [&](Json& bad) {
            bad["media"] = doc["media"], bad["media"]["smoke"]["density"]["bounds"] = {{0, 0, 0}, {2, 0, 1}};
        },
        "media.smoke.density.bounds", "each of the first corner's coordinates must be below the second's");
}

// "emission": Le = radiance * scale, times its grid where the light is; with a temperature
// grid, pbrt-v4's blackbody at (T - offset) * scale; and what is wrong with one, by path.
TEST(MediaScene, AMediumThatEmits) {
    Json doc = test::fullScene();
    doc["media"] = {{"fire",
                     {{"absorption", {1, 1, 1}},
                      {"emission",
                       {{"radiance", {1, 2, 3}},
                        {"scale", 2},
                        {"grid", {{"resolution", {2, 1, 1}}, {"values", {1, 3}}, {"bounds", {{0, 0, 0}, {2, 1, 1}}}}}}}}},
                    {"hot",
                     {{"absorption", {1, 1, 1}},
                      {"emission",
                       {{"temperature", {{"resolution", {1, 1, 1}}, {"values", {1700}}}},
                        {"temperature_offset", 200},
                        {"temperature_scale", 2}}}}}};
    const SceneDescription d = load(doc);
    ASSERT_TRUE(d.media[0].emits());
    EXPECT_VEC3_NEAR(d.media[0].emission->at({0.5f, 0.5f, 0.5f}), Color(2, 4, 6), 1e-5f);
    EXPECT_VEC3_NEAR(d.media[0].emission->at({1.5f, 0.5f, 0.5f}), Color(6, 12, 18), 1e-4f);
    const Color hot = d.media[1].emission->at({0.5f, 0.5f, 0.5f}), expected = blackbodyPeakColor(3000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(hot[c], expected[c], 1e-4f * expected[c]) << c;

    expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["fire"]["absorption"] = {0, 0, 0}; },
                "media.fire.emission", "a medium emits in proportion to its \"absorption\" (sigma_a Le), which is 0");
    expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["fire"]["emission"]["temperature_scale"] = 2; },
                "media.fire.emission.temperature_scale", "applies only with a \"temperature\" grid");
    expectError([&](Json& bad) { bad["media"] = doc["media"], bad["media"]["hot"]["emission"]["temperature_scale"] = 0; },
                "media.hot.emission.temperature_scale", "must be > 0");
    // Homogeneous, it needs shapes it is inside of: not the camera's medium alone.
    expectError(
        [&](Json& bad) {
            bad["media"] = doc["media"], bad["media"]["fire"]["emission"].erase("grid");
            bad["camera"]["medium"] = "fire";
        },
        "media.fire.emission",
        "a homogeneous medium that emits must lie inside shapes that bound it (its light leaves from their box), or "
        "have a \"density\" or emission \"grid\" to say where it is");
}

TEST(MediaScene, Errors) {
    auto withMedia = [](Json& doc) { doc["media"] = {{"wine", {{"absorption", {1, 2, 3}}}}}; };
    expectError(
        [&](Json& doc) {
            withMedia(doc);
            doc["shapes"][3]["medium"] = {{"inside", "beer"}};
        },
        "shapes[3].medium.inside", "unknown medium \"beer\" (define it under \"media\")");
    expectError(
        [&](Json& doc) {
            withMedia(doc);
            doc["shapes"][3]["medium"] = {{"inside", "wine"}, {"outside", "wine"}};
        },
        "shapes[3].medium", "\"inside\" and \"outside\" are the same: the shape bounds no medium");
    expectError(
        [&](Json& doc) {
            withMedia(doc);
            doc["shapes"][3]["medium"] = {{"inside", "wine"}, {"colour", "red"}};
        },
        "shapes[3].medium.colour", "unknown field");
    expectError([&](Json& doc) { doc["media"] = {{"wine", {{"absorption", {1, -2, 3}}}}}; }, "media.wine.absorption[1]",
                "must be >= 0");
    expectError([&](Json& doc) { doc["media"] = {{"wine", Json::object()}}; }, "media.wine",
                "a medium needs \"absorption\", \"scattering\" or both, or \"reflectance\" and \"mean_free_path\"");
    expectError([&](Json& doc) { doc["media"] = {{"skin", {{"reflectance", {0.5, 0.5, 0.5}}}}}; }, "media.skin.mean_free_path",
                "missing required field");
    expectError(
        [&](Json& doc) {
            doc["media"] = {{"skin", {{"reflectance", {0.5, 0.5, 0.5}}, {"mean_free_path", {1, 0, 1}}}}};
        },
        "media.skin.mean_free_path[1]", "must be > 0");
    expectError(
        [&](Json& doc) {
            doc["media"] = {{"skin", {{"reflectance", {0.5, 0.5, 0.5}}, {"mean_free_path", {1, 1, 1}}, {"absorption", {1, 1, 1}}}}};
        },
        "media.skin.absorption",
        "give either \"reflectance\" and \"mean_free_path\" or \"absorption\" and \"scattering\", not both");
    expectError([&](Json& doc) { doc["media"] = {{"wine", {{"absorption", {1, 1, 1}}, {"boundary_ior", 1.4}}}}; },
                "media.wine.boundary_ior", "applies only with \"reflectance\"");
    expectError([&](Json& doc) { doc["media"] = {{"fog", {{"scattering", {1, 1, 1}}, {"g", 1}}}}; }, "media.fog.g",
                "must be in (-1, 1)");
    expectError(
        [&](Json& doc) {
            withMedia(doc);
            doc["camera"]["medium"] = "water";
        },
        "camera.medium", "unknown medium \"water\" (define it under \"media\")");
    expectError(
        [&](Json& doc) {
            withMedia(doc);
            doc["render"]["integrator"] = "radiosity";
        },
        "media", "media are rendered by the \"sppm\" and \"path\" integrators only");
}

}  // namespace
}  // namespace photon
