// pbrt-v4's realistic camera: its lens files read, the system's paraxial focal length against
// the thick-lens equation, and the lenient import's thin lens (the view the focal length
// gives the film at the focus distance, the aperture stop, the focus), refused when strict.
#include <cmath>
#include "import/pbrt/lens_system.h"
#include "pbrt_import_fixture.h"

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
TEST(LensSystem, ADoubleGaussScaledTo50mmHasA50mmFocalLength) {
    const LensFile lens = parseLensFile(R"(# radius  axial distance  index  aperture
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
)");
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

// The importer tests' scene (an area light over a floor) through a realistic camera.
const std::string kRealisticScene = R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "realistic" "string lensfile" "lenses/singlet.dat" "float aperturediameter" [4] "float focusdistance" [5]
Film "rgb" "integer xresolution" [64] "integer yresolution" [32] "float diagonal" [30]
)" + pbrt_import::kHeader.substr(pbrt_import::kHeader.find("WorldBegin"));

TEST(LensSystem, ALenientImportKeepsTheLenssViewApertureAndFocus) {
    using namespace pbrt_import;
    writeScene("realistic/lenses/singlet.dat", kSinglet);
    const fs::path scene = writeScene("realistic/scene.pbrt", kRealisticScene);
    const ImportedScene s = importPbrt(scene, true);
    const Json& camera = s.document["camera"];
    // The film: 30 mm across its diagonal at 2:1, so 13.42 mm high; the focus plane 5 m away
    // images at 1/v = 1/f - 1/5000 mm behind the lens.
    const double f = thickLensFocalLength(1.5, 50, -50, 5);
    const double v = 1 / (1 / f - 1 / 5000.0);
    const double filmHeight = 0.5 * std::sqrt(30.0 * 30.0 / 1.25);
    EXPECT_NEAR(camera["fov"].get<double>(), 2 * std::atan(filmHeight / 2 / v) * 180 / M_PI, 1e-6);
    EXPECT_NEAR(camera["aperture_radius"].get<double>(), 0.002, 1e-12);  // 4 mm, within the 8 mm stop
    EXPECT_EQ(camera["focus_distance"].get<double>(), 5.0);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0],
              "scene.pbrt:3: Camera \"realistic\" (a lens system) is not supported (photon has perspective, "
              "orthographic and spherical cameras); rendered as a thin lens of its paraxial focal length, 50.8 mm at "
              "f/12.7, focused at 5: its distortion, vignetting and aberrations left out (lenient import)");

    // Strict: refused, with its line.
    try {
        importPbrt(scene);
        ADD_FAILURE() << "a realistic camera imported strictly";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "scene.pbrt:3: Camera \"realistic\" (a lens system) is not supported (photon has "
                               "perspective, orthographic and spherical cameras)");
    }
    // A lens file that is not there, even when lenient.
    const fs::path missing = writeScene(
        "realistic/missing.pbrt",
        std::string(kRealisticScene).replace(kRealisticScene.find("lenses/singlet.dat"), 18, "lenses/none.dat"));
    try {
        importPbrt(missing, true);
        ADD_FAILURE() << "a missing lens file imported";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "missing.pbrt:3: Camera \"realistic\": lens file not found: lenses/none.dat");
    }
}

}  // namespace
}  // namespace photon::test
