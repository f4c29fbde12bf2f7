// Media that emit light (docs/scene-format.md#media, description/medium_emission.h): the emission
// estimate along camera paths, and the medium as a light whose photons SPPM gathers, held to
// analytic answers (Beer-Lambert's emission integral, Kirchhoff's equilibrium) and to the
// path tracer.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "import/scene_import.h"
#include "scene/scene_loader.h"
#include "lights/light_factories.h"
#include "math/spectrum_rgb.h"
#include "media/emission_along.h"
#include "math/rng.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// A density of 1 throughout the ball of radius 1 about the origin: 4 x 4 x 4 samples of 1
// over [-1.5, 1.5]^3, whose interpolation is 1 within the box of their centres,
// [-1.125, 1.125]^3, and falls off only beyond.
std::shared_ptr<const DensityGrid> evenGridOverTheBall() {
    return std::make_shared<const DensityGrid>(4, 4, 4, std::vector<float>(64, 1.0f),
                                               DensityGrid::latticeFromBox(4, 4, 4, Vec3(-1.5f), Vec3(1.5f)));
}

MediumDescription glowingMedium(Color absorption, Color scattering, Color radiance) {
    MediumDescription m{"glow", absorption, scattering, 0.3f};
    m.density = evenGridOverTheBall();
    auto e = std::make_shared<MediumEmission>();
    e->radiance = radiance;
    m.emission = e;
    return m;
}

// test::ballOfMedium with 2,000 photons a pass and, if `walls` > 0, instead of the sky a
// closed diffuse sphere of radius 2 and albedo `walls` about the ball, emitting
// (1 - walls) * outside.
SceneDescription insideAGlowingBall(IntegratorKind kind, MediumDescription medium, Color outside, float walls = 0) {
    SceneDescription d = test::ballOfMedium(kind, std::move(medium), walls > 0 ? Color(0.0f) : outside);
    if (walls > 0) {
        d.materials.push_back(makeDiffuse(Color(walls)));
        d.materialNames.push_back("walls");
        d.shapes.push_back(test::sphere({0, 0, 0}, 2.0f, 1, outside * (1 - walls), true));
    }
    d.render.photonsPerPass = 2000;
    return d;
}

// The estimate along one segment against the integral itself: over a homogeneous medium of
// extinction (0.5, 1, 3) with albedo 0.4 in green, emitting (1, 2, 3), a segment of length
// 1.7 from which int_0^L exp(-sigma_t t) sigma_a Le dt = sigma_a Le (1 - exp(-sigma_t L)) /
// sigma_t; and over the ball's even grid, whose density is 1 there, the same.
TEST(EmissionAlong, EstimatesTheIntegralAlongASegment) {
    const Color absorption(0.5f, 0.6f, 3.0f), scattering(0.0f, 0.4f, 0.0f), radiance(1, 2, 3);
    for (bool grid : {false, true}) {
        MediumDescription m = glowingMedium(absorption, scattering, radiance);
        if (!grid) m.density.reset();
        const float length = 1.7f;
        const Color sigmaT = m.extinction();
        Color sum(0.0f);
        constexpr int kSamples = 200000;
        for (int i = 0; i < kSamples; ++i)
            sum += sampleEmissionAlong(m, Vec3(0.0f, 0.0f, 0.85f), Vec3(0, 0, -1), length, (i + 0.5f) / kSamples);
        for (int c = 0; c < 3; ++c) {
            const double expected = absorption[c] * radiance[c] * (1 - std::exp(-sigmaT[c] * length)) / sigmaT[c];
            EXPECT_NEAR(sum[c] / kSamples, expected, 1e-3 * expected) << "grid " << grid << ", channel " << c;
        }
    }
}

// The medium as a light: the mean flux of its photons is the power it emits, 4 pi times
// the integral of sigma_a rho Le over the grid's box, however its cells are drawn. Here the
// density is 8 x 6 x 5 random samples (one row of them all zero) and Le is times a scale
// grid of 3 x 3 x 3 random samples over part of the box, the grid the photons leave from:
// its cells' weights at their centres miss some of the light. The integral by the midpoint
// rule on 160^3 points.
TEST(EmissiveMedium, ItsPhotonsCarryThePowerItEmits) {
    Rng rng(3, 0, 1, StreamPurpose::Camera);
    std::vector<float> values, scales;
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 8; ++i) values.push_back(j == 2 ? 0.0f : 3.0f * rng.uniform() * rng.uniform());
    for (int n = 0; n < 27; ++n) scales.push_back(rng.uniform() < 0.3f ? 0.0f : rng.uniform());
    const Vec3 lo{-1, 0, 2}, hi{3, 1.5f, 4}, scaleLo{-0.5f, 0.2f, 2.5f};
    MediumDescription m{"glow", Color(0.5f, 1.0f, 2.0f), Color(0.0f), 0.0f};
    m.density = std::make_shared<const DensityGrid>(8, 6, 5, values, DensityGrid::latticeFromBox(8, 6, 5, lo, hi));
    auto e = std::make_shared<MediumEmission>();
    e->radiance = Color(1.0f, 0.5f, 0.25f);
    e->scale = std::make_shared<const DensityGrid>(3, 3, 3, scales, DensityGrid::latticeFromBox(3, 3, 3, scaleLo, hi));
    m.emission = e;
    double integral = 0;
    constexpr int kSteps = 160;
    const Vec3 step = (hi - scaleLo) / float(kSteps);
    for (int a = 0; a < kSteps; ++a)
        for (int b = 0; b < kSteps; ++b)
            for (int c = 0; c < kSteps; ++c) {
                const Vec3 p = scaleLo + Vec3{(a + 0.5f) * step.x, (b + 0.5f) * step.y, (c + 0.5f) * step.z};
                integral += double(m.density->at(p)) * e->scale->at(p);
            }
    integral *= double(step.x) * step.y * step.z;
    const std::unique_ptr<Light> light = makeMediumLight(m, m.emissionRegion(), [](Vec3) { return true; });
    Color sum(0.0f);
    constexpr int kPhotons = 400000;
    for (int n = 0; n < kPhotons; ++n) {
        const std::optional<PhotonEmission> p = light->emitPhoton({rng.uniform(), rng.uniform()}, {rng.uniform(), rng.uniform()});
        if (!p) continue;
        ASSERT_TRUE(p->origin.x >= scaleLo.x && p->origin.x <= hi.x && p->origin.z >= scaleLo.z && p->origin.z <= hi.z);
        sum += p->flux;
    }
    for (int c = 0; c < 3; ++c) {
        const double expected = 4 * kPiD * m.absorption[c] * e->radiance[c] * integral;
        EXPECT_NEAR(sum[c] / kPhotons, expected, 0.01 * expected) << "channel " << c;
    }
}

// A ball of glowing gas that only absorbs, seen from its centre: every ray crosses 1 of it,
// so every pixel sees Le (1 - exp(-sigma_a)), by both integrators; and with a temperature
// grid of 3,000 K throughout, pbrt-v4's blackbody at 3,000 K (its peak 1) in place of Le.
// After 64 passes the image's mean deviates from seed to seed by at most 0.06% (16 seeds;
// at 16 passes the path tracer's by 0.27%, which a 0.5% bound held by two deviations),
// held to 0.2%.
TEST(EmissiveMedium, AGlowingBallThatOnlyAbsorbsShowsBeerLambertsIntegral) {
    const Color absorption(0.5f, 1.0f, 2.0f), radiance(1, 2, 3);
    for (bool temperature : {false, true})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            MediumDescription m = glowingMedium(absorption, Color(0.0f), radiance);
            Color le = radiance;
            if (temperature) {
                auto e = std::make_shared<MediumEmission>(*m.emission);
                e->radiance = Color(2.0f);
                e->temperature = std::make_shared<const DensityGrid>(
                    2, 2, 2, std::vector<float>(8, 3500.0f), DensityGrid::latticeFromBox(2, 2, 2, Vec3(-3.0f), Vec3(3.0f)));
                e->temperatureOffset = 500;
                m.emission = e;
                le = 2.0f * blackbodyPeakColor(3000);
            }
            SceneDescription d = insideAGlowingBall(kind, m, Color(0.0f));
            d.render.passes = 64;
            const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
            for (int c = 0; c < 3; ++c) {
                const float expected = le[c] * (1 - std::exp(-absorption[c]));
                EXPECT_NEAR(seen[c], expected, 0.002f * expected)
                    << "integrator " << int(kind) << ", temperature " << temperature << ", channel " << c;
            }
        }
}

// Kirchhoff: a medium that emits Le where it absorbs, in surroundings of radiance Le, is in
// equilibrium with them, so the radiance everywhere in it is Le, whatever it scatters. A
// ball of it (extinction 1.5, 2 and 3 by channel, albedo 1/3 to 2/3) in a sky of Le seen
// from inside, by the path tracer and by SPPM, whose camera paths scatter on through the
// medium ("auto" here), or end at their first scattering point and gather the photons that
// scatter around it, the medium's own from their first scattering on. With volume photons
// 40,000 photons a pass: at 2,000 (the helper's) the image's mean moves by 1.6%, 2.8% and
// 5.1% (standard deviations by channel over 12 seeds, 256 passes) from seed to seed, more
// than the tolerance, because all 256 pixels' balls lie within about half a unit of the
// camera and share their photons; at 40,000, 0.45%, 0.7% and 0.8% (10 seeds; mean 0.998,
// 0.998, 1.002 of Le), so 2.5% is three deviations. The 2-3% shortfall seed 1 showed at
// 2,000 photons, once taken for a bias, is that spread: over 40 seeds at 2,000 the mean is
// 0.997, 0.996 and 1.000 of Le (+-0.2%, 0.4%, 0.9%). Before the medium light tested
// whether its points lie in the medium, the grid's corners outside the ball made that 3-8%
// high.
TEST(EmissiveMedium, AGlowingBallInASkyOfItsOwnRadianceIsInEquilibrium) {
    const MediumDescription m = glowingMedium(Color(1.0f), Color(0.5f, 1.0f, 2.0f), Color(0.8f));
    for (VolumePhotons volume : {VolumePhotons::Auto, VolumePhotons::Always})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            if (kind == IntegratorKind::Path && volume == VolumePhotons::Always) continue;
            SceneDescription d = insideAGlowingBall(kind, m, Color(0.8f));
            d.render.volumePhotons = volume;
            if (volume == VolumePhotons::Always) {
                d.render.photonsPerPass = 40000;
                d.render.adaptivePhotons = false;
            }
            const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
            std::printf("  %s, volume photons %d: %.4f %.4f %.4f\n", kind == IntegratorKind::Path ? "path" : "sppm",
                        int(volume), seen.x, seen.y, seen.z);
            const float tolerance = volume == VolumePhotons::Always ? 0.02f : 0.008f;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(seen[c], 0.8f, tolerance) << "integrator " << int(kind) << ", volume photons " << int(volume)
                                                      << ", channel " << c;
        }
}

// The same equilibrium in a closed cavity: the glowing ball inside a diffuse sphere of
// albedo 0.5 that emits 0.5 * 0.8. The walls take the ball's light from SPPM's photons at
// their first hit (no light sample is taken toward a medium) and their own from light
// samples, so every pixel sees 0.8 there too.
TEST(EmissiveMedium, AGlowingBallInACavityOfItsTemperatureIsInEquilibrium) {
    const MediumDescription m = glowingMedium(Color(1.0f), Color(0.5f, 1.0f, 2.0f), Color(0.8f));
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        SceneDescription d = insideAGlowingBall(kind, m, Color(0.8f), 0.5f);
        d.render.volumePhotons = VolumePhotons::Never;
        // Looking past the ball's edge at the walls from beside it.
        d.camera = test::camera({0, 0, 0.5f}, {0, 0, 3}, {0, 1, 0}, 90, 16, 16);
        const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
        std::printf("  %s: %.4f %.4f %.4f\n", kind == IntegratorKind::Path ? "path" : "sppm", seen.x, seen.y, seen.z);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], 0.8f, 0.012f) << "integrator " << int(kind) << ", channel " << c;
    }
}

// Light from a glowing ball on a grey floor under it, which SPPM's photons bring from their
// first hit and the path tracer's BSDF samples find by crossing the ball: the two agree.
TEST(EmissiveMedium, SppmAgreesWithThePathTracerOnAFloorLitByAGlowingBall) {
    SceneDescription d;
    d.camera = test::camera({0, 3, 4}, {0, 0, 0}, {0, 1, 0}, 50, 24, 24);
    d.materials = {makeDielectric(1.0f), makeDiffuse(Color(0.6f))};
    d.materialNames = {"boundary", "floor"};
    d.media = {glowingMedium(Color(2.0f, 1.0f, 0.5f), Color(0.5f), Color(4.0f))};
    d.shapes = {test::sphere({0, 0, 0}, 1.0f, 0), test::quad({-4, -1.2f, -4}, {0, 0, 8}, {8, 0, 0}, 1)};
    d.shapes[0].insideMedium = 0;
    const test::PathAndSppmMeans means = test::renderPathAndSppm(d, 256, 256, 20000);
    std::printf("  path %.4f %.4f %.4f, sppm %.4f %.4f %.4f\n", means.path.x, means.path.y, means.path.z,
                means.sppm.x, means.sppm.y, means.sppm.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.sppm[c], means.path[c], 0.02f * means.path[c]) << "channel " << c;
}

// pbrt-v4's glowing fog imported and rendered: a sphere of radius 1 holding a homogeneous
// medium that absorbs 0.5 and emits "Le" [1 2 3] times "Lescale" 2, seen through its centre
// from far off (fov 0.2 degrees: the rays cross 2 of it less 0.03% on average), shows
// Le (1 - exp(-2 sigma_a)) by both integrators; its photons leave from a box around the
// sphere (Scene::boxAroundShapesHolding), those outside it spent.
TEST(EmissiveMedium, AnImportedSphereOfGlowingFogShowsBeerLambertsIntegral) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("photon-glow-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "glow.pbrt";
    std::ofstream(file) << R"(LookAt 0 0 20  0 0 0  0 1 0
Camera "perspective" "float fov" [0.2]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
MakeNamedMedium "glow" "string type" "homogeneous" "rgb sigma_a" [0.5 0.5 0.5] "rgb sigma_s" [0 0 0]
  "rgb Le" [1 2 3] "float Lescale" 2
MediumInterface "glow" ""
Material "interface"
Shape "sphere" "float radius" [1]
)";
    for (const char* integrator : {"path", "sppm"}) {
        ImportOptions options;
        SceneDescription d = loadImportedScene(importSceneFile(file, options), dir,
                                               {{"render.integrator", std::string("\"") + integrator + "\""},
                                                {"render.passes", "16"}});
        const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 8, 8);
        for (int c = 0; c < 3; ++c) {
            const float expected = 2.0f * float(c + 1) * (1 - std::exp(-1.0f));
            EXPECT_NEAR(seen[c], expected, 0.003f * expected) << integrator << ", channel " << c;
        }
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace photon
