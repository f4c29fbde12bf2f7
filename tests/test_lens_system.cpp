// pbrt-v4's realistic camera: its lens files read, the system's paraxial focal length against
// the thick-lens equation, its rays traced through a double Gauss (focus, orientation, view),
// the scene format's "realistic" camera and its import.
#include <cmath>
#include <cstdio>
#include "camera/lens_system.h"
#include "import/pbrt/lens_system.h"
#include "math/rng.h"
#include "pbrt_import_fixture.h"
#include "scene_builders.h"
#include "scene_loader_fixture.h"
#include "test_support.h"

namespace photon::test {
namespace {

using namespace photon::pbrt;

// A biconvex singlet (radii +50 and -50 mm, 5 mm of glass of index 1.5) behind an aperture
// stop of 8 mm, the film 40 mm behind it.
const char* const kSinglet = R"(# radius thickness eta aperture
  0    5   0    8    # the stop, in air
 50    5   1.5  20
-50   40   0    20
)";

// The thick lens in air (Hecht, Optics, eq. 6.2): 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)).
double thickLensFocalLength(double n, double r1, double r2, double d) {
    return 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * d / (n * r1 * r2)));
}

TEST(LensSystem, ParaxialFocalLengthIsTheThickLenss) {
    const LensFile lens = parseLensFile(kSinglet);
    ASSERT_EQ(lens.error, "");
    ASSERT_EQ(lens.interfaces.size(), 3u);
    EXPECT_EQ(lens.interfaces[1].eta, 1.5);
    EXPECT_EQ(apertureStopDiameter(lens.interfaces), 8.0);
    const double expected = thickLensFocalLength(1.5, 50, -50, 5);  // 50.85 mm
    EXPECT_NEAR(*paraxialFocalLength(lens.interfaces), expected, 1e-9 * expected);
    // A meniscus of the same glass, thicker: the equation still holds.
    const LensFile meniscus = parseLensFile("30 12 1.6 20\n80 50 0 20\n");
    EXPECT_NEAR(*paraxialFocalLength(meniscus.interfaces), thickLensFocalLength(1.6, 30, 80, 12), 1e-9);
    // A diverging lens does not focus.
    EXPECT_FALSE(paraxialFocalLength(parseLensFile("-50 5 1.5 20\n50 40 0 20\n").interfaces));
}

// A double Gauss of f/2 (US patent 2,673,491, Tronnier; Smith, Modern Lens Design, p. 312)
// scaled to a 50 mm focal length, as lens files for pbrt-v4 carry it: the paraxial trace
// finds its 50 mm through eleven interfaces, the stop among them.
const char* const kDoubleGauss = R"(# radius  axial distance  index  aperture
29.475   3.76   1.67   25.2
84.83    0.12   1      25.2
19.275   4.025  1.67   23
40.77    3.275  1.699  23
12.75    5.705  1      18
0        4.5    0      17.1
-14.495  1.18   1.603  17
40.77    6.065  1.658  20
-20.385  0.19   1      20
437.065  3.22   1.717  20
-39.73   0      1      20
)";

TEST(LensSystem, ADoubleGaussScaledTo50mmHasA50mmFocalLength) {
    const LensFile lens = parseLensFile(kDoubleGauss);
    ASSERT_EQ(lens.error, "");
    EXPECT_NEAR(*paraxialFocalLength(lens.interfaces), 50.0, 0.5);
    EXPECT_EQ(apertureStopDiameter(lens.interfaces), 17.1);
}

TEST(LensSystem, ABadLensFileSaysWhatIsWrong) {
    EXPECT_EQ(parseLensFile("50 5 1.5 20\n-50 x 0 20\n").error, "line 2: \"x\" is not a number");
    EXPECT_EQ(parseLensFile("50 5 1.5\n").error,
              "expected rows of four numbers (radius, thickness, index, aperture diameter in mm), found 3 numbers");
    EXPECT_EQ(parseLensFile("50 5 0.5 20\n").error,
              "row 1: the thickness must be >= 0, the index 0 (air) or >= 1, the aperture > 0");
}

// Where the rays from raster point (x, y) of the double Gauss at f/2 focused at 2 m (35 mm
// film, 64 x 64) cross the plane `z` metres in front of the film: their mean and RMS spread,
// their mean direction, and the share of lens samples the system lets through.
struct RayBundle {
    double meanX = 0, meanY = 0, spread = 0, dirX = 0, dirY = 0, passed = 0;
};
RayBundle bundle(const LensSystem& lens, float x, float y, double z) {
    RayBundle b;
    std::vector<std::pair<double, double>> hits;
    Rng rng(1, 0, 2, StreamPurpose::Camera);
    constexpr int kSamples = 4000;
    for (int n = 0; n < kSamples; ++n) {
        const auto s = lens.sample(x, y, {rng.uniform(), rng.uniform()});
        if (!s) continue;
        const double t = (z - s->origin.z) / s->direction.z;
        hits.push_back({s->origin.x + t * s->direction.x, s->origin.y + t * s->direction.y});
        b.dirX += s->direction.x / s->direction.z, b.dirY += s->direction.y / s->direction.z;
    }
    b.passed = double(hits.size()) / kSamples;
    for (const auto& [hx, hy] : hits) b.meanX += hx / hits.size(), b.meanY += hy / hits.size();
    for (const auto& [hx, hy] : hits) b.spread += ((hx - b.meanX) * (hx - b.meanX) + (hy - b.meanY) * (hy - b.meanY)) / hits.size();
    b.spread = std::sqrt(b.spread);
    b.dirX /= hits.size(), b.dirY /= hits.size();
    return b;
}

// Traced ray by ray, the double Gauss focused at 2 m images a film point to its smallest spot
// on the plane 2 m away (RMS under 0.6 mm), 8 times wider on the plane at 1 m; the
// image is the right way round (the film's top left sees up and left); and a point at the
// middle of the film's right edge looks out at atan of half the film's width over the image
// distance of 2 m (1/v = 1/f - 1/d, d from the front principal plane), within 2%.
TEST(LensSystem, ADoubleGaussFocusesWhereItIsFocused) {
    const LensFile file = parseLensFile(kDoubleGauss);
    const LensSystem lens(file.interfaces, 0, 2.0, 35, 64, 64);
    EXPECT_NEAR(lens.focalLength(), 0.050, 0.0005);
    const RayBundle centre = bundle(lens, 32, 32, 2.0), near = bundle(lens, 32, 32, 1.0);
    EXPECT_GT(centre.passed, 0.5);
    EXPECT_NEAR(centre.meanX, 0, 1e-4);
    EXPECT_NEAR(centre.meanY, 0, 1e-4);
    // Sharpest at 2 m (0.51 mm RMS at f/2, the system's own aberrations; 0.69 mm at 1.9 m,
    // 0.67 mm at 2.1 m, 4.6 mm at 1 m and at 3 m).
    EXPECT_LT(centre.spread, 0.0006);
    EXPECT_LT(centre.spread, bundle(lens, 32, 32, 1.9).spread);
    EXPECT_LT(centre.spread, bundle(lens, 32, 32, 2.1).spread);
    EXPECT_GT(near.spread, 8 * centre.spread);
    const RayBundle topLeft = bundle(lens, 12, 12, 2.0);
    EXPECT_LT(topLeft.dirX, -0.05);
    EXPECT_GT(topLeft.dirY, 0.05);
    const RayBundle right = bundle(lens, 64, 32, 2.0);
    const double f = lens.focalLength(), v = 1 / (1 / f - 1 / (2.0 - lens.filmDistance() - f));
    EXPECT_NEAR(right.dirX, lens.filmWidth() / 2 / v, 0.02 * lens.filmWidth() / 2 / v);
    EXPECT_NEAR(right.dirY, 0, 1e-3);
}

// A white sky (radiance 1) seen through a biconvex singlet whose rear face is its only stop
// (radius R = 5 mm; the front is wider, so every ray through the rear face passes): at the
// film's centre the weights cos^4 theta A / z^2 integrate over the disc of radius r that
// passes to pi r^2 / (z^2 + r^2), z the rear vertex's distance from the film, which is what the
// centre's pixels read, rendered by the path tracer and by SPPM (the camera's weights
// carried by both). pbrt-v4 weighs its realistic camera's rays so.
TEST(LensSystem, AWhiteSkyThroughASingletReadsTheRearFacesSolidAngleIntegral) {
    SceneDescription d;
    d.camera.projection = CameraProjection::LensSystem;
    d.camera.lens = {{50, 2, 1.5, 20}, {-50, 45, 0, 10}};
    d.camera.focusDistance = 5;
    d.camera.filmDiagonal = 3.5;  // pixels of 39 um: the central 16 x 16 within 0.3 mm of the axis
    d.camera.width = d.camera.height = 64;
    d.camera.position = {0, 0, 0}, d.camera.lookAt = {0, 0, -1}, d.camera.up = {0, 1, 0};
    d.materials = {makeDiffuse(Color(0.5f))};
    d.materialNames = {"far"};
    d.shapes = {test::sphere({0, -1000, 0}, 1, 0)};  // out of view
    LightDescription sky;
    sky.kind = LightDescription::Kind::Environment;
    sky.radiance = Color(1.0f);
    d.lights = {sky};
    d.render.passes = 64;
    // The rear face bulges toward the film by its sag s at its rim, so a film ray aimed at
    // the vertex's plane past R z / (z + s) meets the face outside R: the disc that passes.
    const double z = LensSystem(d.camera.lens, 0, 5, 3.5, 64, 64).filmDistance(), rim = 0.005;
    const double sag = 0.05 - std::sqrt(0.05 * 0.05 - rim * rim), r = rim * z / (z + sag);
    const double expected = 3.14159265358979323846 * r * r / (z * z + r * r);
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Sppm}) {
        d.render.integrator = kind;
        const Color seen = test::meanOver(test::renderImage(d), 24, 24, 40, 40);
        std::printf("  %s: %.5f, expected %.5f\n", kind == IntegratorKind::Path ? "path" : "sppm", seen.x, expected);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], expected, 0.01 * expected) << "integrator " << int(kind);
    }
}

// Drawn within the exit pupil's bounds, the rear points of the double Gauss stopped down to
// f/8 pass far more often than drawn over the whole rear element (69% against 11%), and bring
// the same light: the mean weight of 200,000 samples (stopped ones 0) agrees within 2.5% (four
// standard errors of the rear element's estimate) at the film's centre and at a third and two
// thirds of the way to its corner.
TEST(LensSystem, TheExitPupilsBoundsLoseNoLight) {
    const LensFile file = parseLensFile(kDoubleGauss);
    const LensSystem disc(file.interfaces, 6.25, 3.0, 35, 90, 60), pupil(file.interfaces, 6.25, 3.0, 35, 90, 60, true);
    for (float t : {0.0f, 1.0f / 3, 2.0f / 3}) {
        const float x = 45 + 45 * t, y = 30 + 30 * t;
        double sum[2] = {0, 0}, passed[2] = {0, 0};
        Rng rng(4, 0, 2, StreamPurpose::Camera);
        constexpr int kSamples = 200000;
        for (int n = 0; n < kSamples; ++n) {
            const Vec2 u{rng.uniform(), rng.uniform()};
            int k = 0;
            for (const LensSystem* lens : {&disc, &pupil}) {
                if (auto s = lens->sample(x, y, u)) sum[k] += s->weight, passed[k] += 1;
                ++k;
            }
        }
        std::printf("  %.2f of the way: passed %.3f / %.3f, mean weight %.6f / %.6f\n", t, passed[0] / kSamples,
                    passed[1] / kSamples, sum[0] / kSamples, sum[1] / kSamples);
        EXPECT_NEAR(sum[1], sum[0], 0.025 * sum[0]) << t;
        EXPECT_GT(passed[1], 3 * passed[0]) << t;
    }
}

// The scene format's "realistic" camera: its lens rows, stop and film, and what is wrong with
// one, by JSON path.
TEST(LensSystem, TheSceneFormatsRealisticCamera) {
    Json doc = test::fullScene();
    Json rows = Json::array();
    for (const LensInterface& r : parseLensFile(kDoubleGauss).interfaces)
        rows.push_back({r.radius, r.thickness, r.eta, r.apertureDiameter});
    doc["camera"] = {{"type", "realistic"}, {"position", {0, 1, 5}}, {"look_at", {0, 1, 0}}, {"lens", rows},
                     {"aperture_diameter", 8}, {"focus_distance", 3}, {"film_diagonal", 43.3}, {"resolution", {32, 24}}};
    const SceneDescription d = test::load(doc);
    EXPECT_EQ(d.camera.projection, CameraProjection::LensSystem);
    ASSERT_EQ(d.camera.lens.size(), 11u);
    EXPECT_NEAR(d.camera.lens[5].apertureDiameter, 17.1, 1e-5);
    EXPECT_EQ(d.camera.lensApertureDiameter, 8.0f);
    EXPECT_FLOAT_EQ(d.camera.filmDiagonal, 43.3f);
    EXPECT_EQ(d.camera.focusDistance, 3.0f);
    test::expectError([&](Json& bad) { bad["camera"] = doc["camera"], bad["camera"]["lens"][2] = {1, 2, 3}; },
                      "camera.lens[2]", "must be [radius, thickness, index, aperture diameter] (mm)");
    test::expectError([&](Json& bad) { bad["camera"] = doc["camera"], bad["camera"]["lens"][2][2] = 0.5; },
                      "camera.lens[2]", "the thickness must be >= 0, the index 0 (air) or >= 1, the aperture > 0");
    test::expectError([&](Json& bad) { bad["camera"] = doc["camera"], bad["camera"]["focus_distance"] = 0.05; },
                      "camera.lens", "the lens system cannot focus at 0.050000 m: it is too near for its focal length of 50.358153 mm");
    test::expectError([&](Json& bad) { bad["camera"] = doc["camera"], bad["camera"]["fov"] = 40; },
                      "camera.fov", "is not used by a realistic camera (its lens and film make its view)");
    test::expectError([&](Json& bad) { bad["camera"]["lens"] = rows; }, "camera.lens", "is only used by a realistic camera");
}

// The importer tests' scene (an area light over a floor) through a realistic camera.
const std::string kRealisticScene = R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "realistic" "string lensfile" "lenses/singlet.dat" "float aperturediameter" [4] "float focusdistance" [5]
  "float shutterclose" [0.5]
Film "rgb" "integer xresolution" [64] "integer yresolution" [32] "float diagonal" [30]
)" + pbrt_import::kHeader.substr(pbrt_import::kHeader.find("WorldBegin"));

// pbrt-v4's realistic camera imports as photon's: its lens file's rows, aperture, focus and
// film; the lights scaled by its shutter twice, as pbrt-v4's RealisticCamera weighs its rays
// by the exposure time on top of its sensor's.
TEST(LensSystem, APbrtRealisticCameraImportsItsLens) {
    using namespace pbrt_import;
    writeScene("realistic/lenses/singlet.dat", kSinglet);
    const fs::path scene = writeScene("realistic/scene.pbrt", kRealisticScene);
    const ImportedScene s = importPbrt(scene);
    const Json& camera = s.document["camera"];
    EXPECT_EQ(camera["type"], "realistic");
    EXPECT_EQ(camera["lens"], Json::parse("[[0, 5, 0, 8], [50, 5, 1.5, 20], [-50, 40, 0, 20]]"));
    EXPECT_EQ(camera["aperture_diameter"], 4.0);
    EXPECT_EQ(camera["focus_distance"], 5.0);
    EXPECT_EQ(camera["film_diagonal"], 30.0);
    EXPECT_FALSE(camera.contains("fov"));
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    // The header's area light, times 0.5 for the sensor and 0.5 for the camera.
    EXPECT_EQ(s.document["shapes"][0]["emission_scale"], 0.25);
    // It loads: the singlet focuses at 5 m.
    EXPECT_NO_THROW(loadImportedScene(s, scene.parent_path()));
    // A lens file that is not there.
    const fs::path missing = writeScene(
        "realistic/missing.pbrt",
        std::string(kRealisticScene).replace(kRealisticScene.find("lenses/singlet.dat"), 18, "lenses/none.dat"));
    try {
        importPbrt(missing);
        ADD_FAILURE() << "a missing lens file imported";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "missing.pbrt:3: Camera \"realistic\": lens file not found: lenses/none.dat");
    }
}

}  // namespace
}  // namespace photon::test
