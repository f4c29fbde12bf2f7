// Media that scatter (docs/scene-format.md#media): the Henyey-Greenstein phase function,
// free-flight sampling, and camera paths and photons that scatter in a medium, held to
// analytic answers and to each other.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "import/pbrt/pbrt_import.h"
#include "media/free_flight.h"
#include "media/henyey_greenstein.h"
#include "materials/material.h"
#include "math/rng.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "test_support.h"

namespace photon {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// The phase function integrates to 1 over the sphere and its samples follow it: the
// fraction of samples in each of 20 bins of cos theta matches the integral of p there
// (2 pi times the bin's integral over cos theta) within 4 standard errors, and their mean
// cosine with the forward direction -wo is g.
TEST(HenyeyGreenstein, IntegratesToOneAndSamplesFollowIt) {
    for (float g : {-0.7f, -0.2f, 0.0f, 0.0005f, 0.3f, 0.85f}) {
        double integral = 0;
        constexpr int kSteps = 200000;
        for (int i = 0; i < kSteps; ++i) {
            const double c = -1 + (i + 0.5) * 2.0 / kSteps;
            integral += 2 * kPiD * henyeyGreenstein(float(c), g) * 2.0 / kSteps;
        }
        EXPECT_NEAR(integral, 1.0, 1e-4) << "g " << g;

        const Vec3 wo = normalize(Vec3{0.3f, -0.5f, 0.8f});
        constexpr int kBins = 20, kSamples = 400000;
        std::vector<int> counts(kBins, 0);
        double meanForward = 0;
        Rng rng(7, 0, 3, StreamPurpose::Camera);
        for (int i = 0; i < kSamples; ++i) {
            const PhaseSample s = sampleHenyeyGreenstein(wo, g, {rng.uniform(), rng.uniform()});
            ASSERT_NEAR(length(s.wi), 1.0f, 1e-4f);
            const float c = dot(wo, s.wi);
            ASSERT_NEAR(s.pdf, henyeyGreenstein(c, g), 1e-4f * s.pdf + 1e-6f);
            counts[std::min(kBins - 1, int((c + 1) / 2 * kBins))]++;
            meanForward += dot(-wo, s.wi);
        }
        EXPECT_NEAR(meanForward / kSamples, g, 0.004) << "g " << g;
        for (int b = 0; b < kBins; ++b) {
            double p = 0;
            for (int i = 0; i < 1000; ++i) {
                const double c = -1 + (b + (i + 0.5) / 1000) * 2.0 / kBins;
                p += 2 * kPiD * henyeyGreenstein(float(c), g) * 2.0 / kBins / 1000;
            }
            const double expected = p * kSamples, sigma = std::sqrt(expected * (1 - p)) + 1;
            EXPECT_NEAR(counts[b], expected, 4 * sigma) << "g " << g << ", bin " << b;
        }
    }
}

// The weights of `samples` free flights from the origin along z over [0, length], summed
// over those that scatter in [a, b) and over those that reach the end.
struct FlightTally {
    Color inBin{0.0f}, through{0.0f};
};
FlightTally tallyFlights(const MediumDescription& m, float length, float a, float b, int samples, uint64_t seed) {
    FlightTally tally;
    Rng rng(seed, 0, 5, StreamPurpose::Camera);
    for (int i = 0; i < samples; ++i) {
        Color beta(1.0f);
        ChromaticFlight firstFlight;
        const float t = sampleFreeFlight(m, Vec3(0.0f), Vec3(0, 0, 1), length, rng.uniform(), beta, firstFlight);
        if (t >= length) {
            EXPECT_EQ(t, length);
            tally.through += beta;
        } else if (t >= a && t < b) {
            tally.inBin += beta;
        }
    }
    return tally;
}

// Free flight over a segment of length 0.7 in a medium whose extinction differs by
// channel: per channel, the weight of flights that scatter in [a, b) averages
// sigma_s (exp(-sigma_t a) - exp(-sigma_t b)) / sigma_t, and of those that reach the end
// exp(-sigma_t 0.7), within 1%.
TEST(FreeFlight, WeightsAverageToTheTransportEquationsTerms) {
    MediumDescription m{"fog", Color(0.5f, 1.0f, 0.0f), Color(0.5f, 1.0f, 4.0f), 0.0f};
    const float length = 0.7f, a = 0.2f, b = 0.5f;
    constexpr int kSamples = 1000000;
    const FlightTally tally = tallyFlights(m, length, a, b, kSamples, 11);
    const Color sigmaT = m.extinction();
    for (int c = 0; c < 3; ++c) {
        const double expectedBin = m.scattering[c] * (std::exp(-sigmaT[c] * a) - std::exp(-sigmaT[c] * b)) / sigmaT[c];
        EXPECT_NEAR(tally.inBin[c] / kSamples, expectedBin, 0.01 * expectedBin) << "channel " << c;
        const double expectedThrough = std::exp(-sigmaT[c] * length);
        EXPECT_NEAR(tally.through[c] / kSamples, expectedThrough, 0.01 * expectedThrough) << "channel " << c;
    }
}

// Free flights through a density ramp rho(z) = z over [0, 2] (extinction 1, 2, 0.5 by
// channel, albedo 1/2): the weight of the flights that scatter in [a, b) averages
// sigma_s int_a^b rho exp(-sigma_t D(z)) dz = sigma_s / sigma_t (exp(-sigma_t D(a)) -
// exp(-sigma_t D(b))), D(z) = z^2 / 2, and of those that go through, exp(-sigma_t D(2)).
TEST(FreeFlight, FlightsFollowAVaryingDensity) {
    // Samples max(z, 0) at z = -1, -0.75, ..., 2.75 (the centres of a 16-cell box over
    // [-1.125, 2.875]), so that rho = z on [0, 2], where the flights go.
    std::vector<float> values;
    for (int k = 0; k < 16; ++k) values.push_back(std::max(0.0f, -1.0f + k * 0.25f));
    MediumDescription m{"ramp", Color(0.5f, 1.0f, 0.25f), Color(0.5f, 1.0f, 0.25f), 0.0f};
    m.density = std::make_shared<const DensityGrid>(
        1, 1, 16, std::move(values), DensityGrid::latticeFromBox(1, 1, 16, {-50, -50, -1.125f}, {50, 50, 2.875f}));
    const float a = 0.6f, b = 1.3f, length = 2.0f;
    constexpr int kSamples = 400000;
    const FlightTally tally = tallyFlights(m, length, a, b, kSamples, 3);
    const Color sigmaT = m.extinction();
    auto D = [](double z) { return z * z / 2; };
    for (int c = 0; c < 3; ++c) {
        const double bin = m.scattering[c] / sigmaT[c] * (std::exp(-sigmaT[c] * D(a)) - std::exp(-sigmaT[c] * D(b)));
        EXPECT_NEAR(tally.inBin[c] / kSamples, bin, 0.015 * bin) << "channel " << c;
        const double go = std::exp(-sigmaT[c] * D(length));
        EXPECT_NEAR(tally.through[c] / kSamples, go, 0.015 * go) << "channel " << c;
    }
}

// A slab of fog (z in [-0.5, 0.5], wide, bounded by an index-1 dielectric) under a distant
// light of irradiance E shining straight down, seen from straight above by an orthographic
// camera, with nothing below. Light scattered once back toward the camera is
//   L = E sigma_s p(1) (1 - exp(-2 sigma_t H)) / (2 sigma_t),
// p(1) the phase function's value for wi = wo (straight back), H = 1. render.max_depth 1
// keeps single scattering alone; the path tracer and SPPM agree with it within 1%. The two
// tests render 512 passes: over 12 seeds the image's mean deviates by 0.12% (SPPM) and
// 0.25% (the path tracer) a seed, means 0.9998 and 0.9992 (at 64 passes the path tracer's
// deviated by 1%).
SceneDescription fogSlab(IntegratorKind kind, int maxDepth) {
    SceneDescription d;
    d.camera = test::orthographicCamera({0, 0, 3}, {0, 0, 0}, 0.5f, 8, 8);
    d.materials = {makeDielectric(1.0f)};
    d.materialNames = {"boundary"};
    d.media = {{"fog", Color(0.5f, 0.25f, 0.0f), Color(0.5f, 1.0f, 1.5f), 0.3f}};
    d.shapes = test::boxFaces({-50, -50, -0.5f}, {50, 50, 0.5f}, 0, 0);
    LightDescription sun;
    sun.kind = LightDescription::Kind::Directional;
    sun.direction = {0, 0, -1};
    sun.irradiance = Color(10.0f);
    d.lights = {sun};
    d.render.integrator = kind;
    d.render.maxDepth = maxDepth;
    d.render.passes = 64;
    d.render.photonsPerPass = 2000;
    return d;
}

TEST(ScatteringMedium, SingleScatteringInASlabMatchesTheIntegral) {
    const MediumDescription fog = fogSlab(IntegratorKind::Path, 1).media[0];
    const Color sigmaT = fog.extinction();
    const float p = henyeyGreenstein(1.0f, fog.g);
    for (VolumePhotons volume : {VolumePhotons::Never, VolumePhotons::Always})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            SceneDescription d = fogSlab(kind, 1);
            d.render.passes = 512;
            d.render.volumePhotons = volume;
            const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 8, 8);
            for (int c = 0; c < 3; ++c) {
                const float expected = 10.0f * fog.scattering[c] * p * (1 - std::exp(-2 * sigmaT[c])) / (2 * sigmaT[c]);
                EXPECT_NEAR(seen[c], expected, 0.01f * expected)
                    << "integrator " << int(kind) << ", volume photons " << int(volume) << ", channel " << c;
            }
        }
}

// The same slab with a density that varies with depth (a grid of 3 x 3 x 6 samples over the
// slab, equal across x and y, where the camera looks): single scattering of light from
// straight above, seen from straight above, depends on the column's density only through
// its integral D, L = E sigma_s p(1) (1 - exp(-2 sigma_t D)) / (2 sigma_t), since
// d/dz exp(-2 sigma_t D(z)) = 2 sigma_t rho(z) exp(-2 sigma_t D(z)).
TEST(ScatteringMedium, SingleScatteringInASlabOfVaryingDensityMatchesTheIntegral) {
    const std::vector<float> column = {0.2f, 1.5f, 0.7f, 2.0f, 0.4f, 1.1f};
    std::vector<float> values;
    for (float v : column)
        for (int k = 0; k < 9; ++k) values.push_back(v);
    // Samples at the centres of 6 cells of 1/6 over z in [-0.5, 0.5]: over the half cell
    // to each face the density falls to half the outermost sample's.
    const float h = 1.0f / 6;
    double D = 3 * h / 8 * (column.front() + column.back());
    for (size_t k = 0; k + 1 < column.size(); ++k) D += h * (column[k] + column[k + 1]) / 2;
    const auto grid = std::make_shared<const DensityGrid>(
        3, 3, 6, std::move(values), DensityGrid::latticeFromBox(3, 3, 6, {-50, -50, -0.5f}, {50, 50, 0.5f}));
    for (VolumePhotons volume : {VolumePhotons::Never, VolumePhotons::Always})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            SceneDescription d = fogSlab(kind, 1);
            d.render.passes = 512;
            d.media[0].density = grid;
            d.render.volumePhotons = volume;
            const MediumDescription fog = d.media[0];
            const Color sigmaT = fog.extinction();
            const float p = henyeyGreenstein(1.0f, fog.g);
            const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 8, 8);
            for (int c = 0; c < 3; ++c) {
                const double expected = 10.0 * fog.scattering[c] * p * (1 - std::exp(-2 * sigmaT[c] * D)) / (2 * sigmaT[c]);
                EXPECT_NEAR(seen[c], expected, 0.01 * expected)
                    << "integrator " << int(kind) << ", volume photons " << int(volume) << ", channel " << c;
            }
        }
}

// A ball of fog that absorbs nothing (albedo 1 in every channel, extinction 1, 2 and 4 by
// channel, g 0.5) in a white sky, seen from inside: light is neither lost nor made, so
// every pixel sees 1 (a white furnace for the phase function's sampling, the light samples'
// in the medium, and their weighting).
TEST(ScatteringMedium, AWhiteFurnaceOfFogStaysWhite) {
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        const Color seen = test::meanOver(
            test::renderImage(test::ballOfMedium(kind, {"fog", Color(0.0f), Color(1.0f, 2.0f, 4.0f), 0.5f}, Color(1.0f))), 0, 0, 16, 16);
        std::printf("  %s: %.4f %.4f %.4f\n", kind == IntegratorKind::Path ? "path" : "sppm", seen.x, seen.y, seen.z);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], 1.0f, 0.01f) << "integrator " << int(kind) << ", channel " << c;
    }
}

// The white furnace with a ball of smoke whose density varies from 0 to 2 over a lattice
// of 8 x 8 x 8 samples: light is still neither lost nor made, so the flights drawn on the
// density's integral and the transmittance of the light samples' shadow rays through it
// must agree, for the path tracer and for SPPM's camera paths. (SPPM gathering photons where
// they scatter is held to single scattering in the uneven slab above: in this furnace it
// read up to 7% low in blue at 256 passes, as it did in the same ball of even fog, with or
// without the grid.)
TEST(ScatteringMedium, AWhiteFurnaceOfUnevenSmokeStaysWhite) {
    std::vector<float> values;
    Rng rng(5, 0, 1, StreamPurpose::Camera);
    for (int i = 0; i < 512; ++i) values.push_back(2.0f * rng.uniform());
    MediumDescription smoke{"smoke", Color(0.0f), Color(1.0f, 2.0f, 4.0f), 0.5f};
    smoke.density = std::make_shared<const DensityGrid>(
        8, 8, 8, std::move(values), DensityGrid::latticeFromBox(8, 8, 8, Vec3(-1.0f), Vec3(1.0f)));
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        SceneDescription d = test::ballOfMedium(kind, smoke, Color(1.0f));
        d.render.volumePhotons = VolumePhotons::Never;
        const Color seen = test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], 1.0f, 0.01f) << "integrator " << int(kind) << ", channel " << c;
    }
}

// pbrt-v4's "subsurface" material, imported as what it models (a dielectric boundary around
// a scattering medium): a ball of Spectralon (Jensen et al.'s measurement, which absorbs
// nothing) behind glass of index 1.5, in a white sky of radiance 1, seen from outside. Light
// is neither lost nor made, through refraction, total internal reflection and tens of
// scatterings, so the ball is as white as the sky: for the path tracer, for SPPM's camera
// paths through the medium, and for SPPM gathering photons where they scatter in it
// (volume photons, which "auto" chooses here), whose balls reach past the glass near it
// (storeVolumePoint counts only their part inside; without that, 3-6% dark). The medium is
// imported as a subsurface one; rendered as the volume it is (`subsurface` off), its walks
// counted vertex by vertex, refracted in and out, with volume photons where "auto" has them.
TEST(ScatteringMedium, AnImportedSubsurfaceBallOfSpectralonInAWhiteSkyIsWhite) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("photon-subsurface-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "ball.pbrt") << R"(
LookAt 0 0 4  0 0 0  0 1 0
Camera "perspective" "float fov" [20]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "subsurface" "string name" "Spectralon" "float scale" 0.2 "float eta" 1.5
Shape "sphere" "float radius" 1
)";
    const ImportedScene imported = importPbrt(folder / "ball.pbrt");
    std::filesystem::remove_all(folder);
    struct Variant {
        const char* name;
        IntegratorKind integrator;
        VolumePhotons volume;
        int passes;
        float tolerance;
    };
    for (const Variant& v : {Variant{"path", IntegratorKind::Path, VolumePhotons::Auto, 1024, 0.01f},
                             Variant{"sppm, camera paths", IntegratorKind::Sppm, VolumePhotons::Never, 512, 0.01f},
                             Variant{"sppm, volume photons", IntegratorKind::Sppm, VolumePhotons::Auto, 2048, 0.02f}}) {
        SceneDescription d = loadImportedScene(imported, folder);
        ASSERT_TRUE(d.media.at(0).subsurface);
        d.media[0].subsurface = false;
        d.render.integrator = v.integrator;
        d.render.maxDepth = 400;
        d.render.passes = v.passes;
        d.render.photonsPerPass = 2000;
        d.render.volumePhotons = v.volume;
        // The ball fills the middle 8 x 8 pixels (radius 1 at distance 4 in a 20 degree view).
        const Color seen = test::meanOver(test::renderImage(std::move(d)), 4, 4, 12, 12);
        std::printf("  %s: %.4f %.4f %.4f\n", v.name, seen.x, seen.y, seen.z);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], 1.0f, v.tolerance) << v.name << ", channel " << c;
    }
}

// A grey floor under a layer of fog, lit by a point light above the fog, seen from above
// through it. The floor's light has come through the fog unscattered (light samples) and
// scattered on the way (photons that scatter in the fog before they land, for SPPM; the
// path tracer's paths through the fog), and the fog's own light toward the camera comes
// from the camera paths' light samples in it and from the floor's photons: SPPM's image
// agrees with the path tracer's in mean within 2% per channel.
TEST(ScatteringMedium, SppmAgreesWithThePathTracerUnderALayerOfFog) {
    auto scene = [](IntegratorKind kind, int passes) {
        SceneDescription d;
        d.camera = test::camera({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40, 16, 16);
        d.materials = {makeDiffuse(Color(0.6f)), makeDielectric(1.0f)};
        d.materialNames = {"floor", "boundary"};
        d.media = {{"fog", Color(0.2f), Color(0.8f, 1.2f, 1.6f), 0.4f}};
        d.shapes = {test::quad({-4, -4, 0}, {8, 0, 0}, {0, 8, 0}, 0)};
        for (const ShapeDescription& face : test::boxFaces({-4, -4, 0.5f}, {4, 4, 1.5f}, 1, 0)) d.shapes.push_back(face);
        d.lights = {test::pointLight({0.3f, -0.2f, 2.5f}, Color(20.0f))};
        d.render.integrator = kind;
        d.render.passes = passes;
        d.render.photonsPerPass = 20000;
        d.render.adaptivePhotons = false;
        d.render.maxDepth = 12;
        return test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
    };
    const Color path = scene(IntegratorKind::Path, 512), sppm = scene(IntegratorKind::Sppm, 128);
    std::printf("  path %.4f %.4f %.4f  sppm %.4f %.4f %.4f\n", path.x, path.y, path.z, sppm.x, sppm.y, sppm.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sppm[c], path[c], 0.02f * path[c]) << "channel " << c;
}

// A volumetric caustic, by the method of images: fog over a perfect mirror, lit by a point
// light inside the fog, looks the same from above as a layer of fog twice as thick lit by
// the light and its mirror image below it, with no mirror. In the first, the light the
// mirror sends into the fog reaches a point there only along a specular path, which no light
// sample finds: photons that scatter in the fog bring it (render.volume_photons). The
// second has no specular path, and the path tracer renders it. Near a point light in fog
// every light sample where a free flight scatters carries 1 / r^2: the camera paths also
// sample the lights along their rays (render.equiangular), without which the path tracer's
// image moved by 1.9% from seed to seed at 1,024 passes (0.30% with them; 8 seeds).
Color foggyMirrorImage(IntegratorKind kind, bool byImages, VolumePhotons volumePhotons, int passes) {
    SceneDescription d;
    d.camera = test::orthographicCamera({0, 0, 3}, {0, 0, 0}, 2.0f, 16, 16);
    d.materials = {makeDielectric(1.0f), makeMirror(Color(1.0f))};
    d.materialNames = {"boundary", "mirror"};
    d.media = {{"fog", Color(0.1f), Color(0.5f), 0.3f}};
    d.shapes = test::boxFaces({-20, -20, byImages ? -1.0f : 0.0f}, {20, 20, 1}, 0, 0);
    if (!byImages) d.shapes[4].material = 1;  // the floor (-z) is the mirror
    d.lights = {test::pointLight({0.2f, -0.1f, 0.4f}, Color(4.0f), 0)};
    if (byImages) d.lights.push_back(test::pointLight({0.2f, -0.1f, -0.4f}, Color(4.0f), 0));
    d.render.integrator = kind;
    d.render.volumePhotons = volumePhotons;
    d.render.maxDepth = 16;
    d.render.passes = passes;
    d.render.photonsPerPass = 20000;
    return test::meanOver(test::renderImage(std::move(d)), 0, 0, 16, 16);
}

TEST(ScatteringMedium, PhotonsInTheFogBringTheLightOfAMirror) {
    const Color images = foggyMirrorImage(IntegratorKind::Path, true, VolumePhotons::Auto, 1024);
    const Color sppm = foggyMirrorImage(IntegratorKind::Sppm, false, VolumePhotons::Auto, 256);
    const Color surfacesOnly = foggyMirrorImage(IntegratorKind::Sppm, false, VolumePhotons::Never, 256);
    std::printf("  path (images) %.4f  sppm %.4f  sppm, photons on surfaces only %.4f\n", images.x, sppm.x,
                surfacesOnly.x);
    // Over 12 seeds SPPM reads 0.9987 of the path tracer's image, the two deviating from
    // each other by 0.58% a seed; 0.981 before the balls by the mirror, which camera paths
    // from above have not turned at, were corrected for their part below it, the plane
    // their rays would have gone on to (docs/sppm.md, "A ball cut by the medium's edge").
    EXPECT_NEAR(sppm.x, images.x, 0.025f * images.x);
    // What the test tells apart: with photons on surfaces alone the mirror's light in the
    // fog is missing (0.805 of the image over 12 seeds, at most 0.810).
    EXPECT_LT(surfacesOnly.x, 0.9f * images.x);
}

// The same seed gives the same image on one thread and on two through chromatic fog: each
// camera path's and photon's flights draw from their own streams.
TEST(ScatteringMedium, FogImageIsTheSameOnOneAndTwoThreads) {
    for (VolumePhotons volume : {VolumePhotons::Never, VolumePhotons::Always})
        for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
            SceneDescription d = fogSlab(kind, 8);
            d.render.passes = 4;
            d.render.volumePhotons = volume;
            d.shapes.push_back(test::quad({-2, -2, -1}, {4, 0, 0}, {0, 4, 0}, 1));
            d.materials.push_back(makeDiffuse(Color(0.5f)));
            d.materialNames.push_back("floor");
            EXPECT_TRUE(test::renderWithThreads(d, 1).rgb == test::renderWithThreads(d, 2).rgb)
                << "integrator " << int(kind) << ", volume photons " << int(volume);
        }
}

}  // namespace
}  // namespace photon
