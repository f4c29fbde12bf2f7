// Curves and the hair material in renders: the share of light a row of fibres stops (their
// projected width over their spacing), a white furnace of fibres that absorb nothing (every
// pixel sees exactly the environment's radiance), and SPPM against the path tracer on a
// tuft of brown hair over a floor.
#include <gtest/gtest.h>
#include <cmath>
#include "materials/material.h"
#include "math/rng.h"
#include <photon/render.h>
#include "scene/scene.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

// Straight fibres (linear, two points each) of radius r between the given ends.
ShapeDescription fibres(const std::vector<std::pair<Vec3, Vec3>>& ends, float r, CurveProfile profile, uint32_t material) {
    ShapeDescription s;
    s.kind = ShapeDescription::Kind::Curves;
    s.curves.basis = CurveBasis::Linear;
    s.curves.profile = profile;
    for (const auto& [a, b] : ends) {
        s.curves.strandStarts.push_back(uint32_t(s.curves.points.size()));
        s.curves.points.push_back({a, r});
        s.curves.points.push_back({b, r});
    }
    s.material = material;
    s.name = "fibres";
    return s;
}

// `count` random Bezier strands, each a smooth arc through a ball of radius 0.5 at the
// origin (a tuft of hair), radius r.
ShapeDescription tuft(int count, float r, uint32_t material, uint64_t seed) {
    ShapeDescription s;
    s.kind = ShapeDescription::Kind::Curves;
    s.curves.basis = CurveBasis::Bezier;
    Rng rng(seed, 0, 0, StreamPurpose::Test);
    auto inBall = [&] {
        for (;;) {
            Vec3 p(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
            if (lengthSquared(p) <= 1) return p * 0.5f;
        }
    };
    for (int k = 0; k < count; ++k) {
        s.curves.strandStarts.push_back(uint32_t(s.curves.points.size()));
        for (int i = 0; i < 4; ++i) s.curves.points.push_back({inBall(), r});
    }
    s.material = material;
    s.name = "tuft";
    return s;
}

// An orthographic view straight down -z onto a row of black fibres along y, spaced s = 0.1
// apart in x, radius 0.01, before an emitter of radiance 1: each ray is stopped with
// probability 2 r / s, so the image's mean is 1 - 0.2, round tubes and flat ribbons alike.
// 32 x 32 pixels x 16 passes: the binomial error of the mean is 0.0016.
TEST(CurvesRender, RowOfFibresStopsTheirWidthOverTheirSpacing) {
    for (CurveProfile profile : {CurveProfile::Round, CurveProfile::Flat}) {
        SceneDescription d;
        d.camera = test::orthographicCamera({0, 0, 5}, {0, 0, 0}, 1.3f, 32, 32);
        d.materials = {makeDiffuse(Color(0.0f))};
        d.materialNames = {"black"};
        std::vector<std::pair<Vec3, Vec3>> ends;
        for (int k = 0; k < 40; ++k) {
            const float x = -2.0f + 0.1f * float(k) + 0.05f;
            ends.push_back({{x, -2, 0}, {x, 2, 0}});
        }
        d.shapes = {test::quad({-3, -3, -1}, {6, 0, 0}, {0, 6, 0}, 0, Color(1.0f)), fibres(ends, 0.01f, profile, 0)};
        d.render.integrator = IntegratorKind::Path;
        d.render.passes = 16;
        const Image image = test::renderImage(d);
        const Color mean = test::meanOver(image, 0, 0, 32, 32);
        EXPECT_NEAR(mean.x, 0.8f, 0.006f) << (profile == CurveProfile::Round ? "round" : "flat");
    }
}

// Fibres that absorb nothing (sigma_a = 0) under a uniform environment of radiance 1: the
// hair model's four terms add up to all the light (A_0 + A_1 + A_2 + A_3 = 1), so whatever
// the paths do among the fibres, every pixel sees radiance 1, to the BSDF's own energy error
// (test_hair's furnace) and the noise.
TEST(CurvesRender, WhiteFurnaceOfFibresThatAbsorbNothing) {
    SceneDescription d;
    d.camera = test::camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 16, 24, 24);
    HairParameters clear;
    clear.sigmaA = Color(0.0f);
    d.materials = {makeHair(clear)};
    d.materialNames = {"clear hair"};
    d.shapes = {tuft(400, 0.004f, 0, 7)};
    LightDescription sky;
    sky.kind = LightDescription::Kind::Environment;
    sky.radiance = Color(1.0f);
    d.lights = {sky};
    d.render.maxDepth = 200;
    d.render.passes = 16;
    d.render.photonsPerPass = 20000;
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        d.render.integrator = kind;
        Renderer renderer(Scene::build(d));
        CancelToken cancel;
        RenderProgress last;
        renderer.run(cancel, [&](const RenderProgress& p) { last = p; });
        const Color mean = test::meanOver(renderer.snapshot(), 4, 4, 20, 20);
        EXPECT_NEAR(mean.x, 1.0f, 0.02f) << "integrator " << int(kind);
        EXPECT_NEAR(mean.z, 1.0f, 0.02f) << "integrator " << int(kind);
        // Fibres and sky keep no visible point, so SPPM traces no photons at all.
        if (kind == IntegratorKind::Sppm) {
            EXPECT_EQ(last.photonsTraced, 0);
            EXPECT_EQ(last.lastPass.photonRays, 0);
        }
    }
}

// A tuft of `strands` strands of hair over a grey floor under a square light.
SceneDescription hairOverAFloor(float eumelanin, int strands, uint64_t seed, int resolution) {
    SceneDescription d;
    d.camera = test::camera({0, 1.2f, 3}, {0, 0.3f, 0}, {0, 1, 0}, 40, resolution, resolution);
    HairParameters h;
    h.sigmaA = hairSigmaAFromMelanin(eumelanin, 0.0f);
    d.materials = {makeDiffuse(Color(0.6f)), makeHair(h)};
    d.materialNames = {"grey", "hair"};
    ShapeDescription hair = tuft(strands, 0.006f, 1, seed);
    for (CurvePoint& p : hair.curves.points) p.p += Vec3(0, 0.6f, 0);
    d.shapes = {test::quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0),
                test::quad({-0.5f, 2.5f, -0.5f}, {1, 0, 0}, {0, 0, 1}, 0, Color(8.0f)), hair};
    return d;
}

// A tuft of brown hair (eumelanin 1.3) over the floor: the light the floor gets through the
// hair is photons' in SPPM and light samples' and BSDF samples' in the path tracer; the hair
// itself is path traced by both. The two images' means agree within 3% per channel.
TEST(CurvesRender, SppmAgreesWithThePathTracerOnHairOverAFloor) {
    const SceneDescription d = hairOverAFloor(1.3f, 600, 3, 24);
    const test::PathAndSppmMeans means = test::renderPathAndSppm(d, 64, 64, 50000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.sppm[c], means.path[c], 0.03f * means.path[c]) << "channel " << c;
}

// The same seed gives the same image on one thread and on two, through hair: the curves'
// hits and the filter that skips the fibre a ray leaves depend on the ray alone.
TEST(CurvesRender, HairImageIsTheSameOnOneAndTwoThreads) {
    SceneDescription d = hairOverAFloor(0.3f, 300, 5, 16);  // blonde
    d.render.passes = 4;
    d.render.photonsPerPass = 20000;
    for (IntegratorKind kind : {IntegratorKind::Sppm, IntegratorKind::Path}) {
        d.render.integrator = kind;
        EXPECT_TRUE(test::renderWithThreads(d, 1).rgb == test::renderWithThreads(d, 2).rgb) << "integrator " << int(kind);
    }
}

}  // namespace
}  // namespace photon
