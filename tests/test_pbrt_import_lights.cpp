// The pbrt-v4 importer's lights: point, spot, distant and infinite lights, portals, pbrt's
// illuminance, and an environment light's frame, against values worked out by hand.
#include <gtest/gtest.h>
#include <cmath>
#include <photon/errors.h>
#include "description/scene_description.h"
#include "import/pbrt/pbrt_import.h"
#include "lights/light_factories.h"
#include "pbrt_import_fixture.h"
#include "scene_loader_fixture.h"
#include "scene/ply_mesh.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon {
namespace {

using namespace test::pbrt_import;

TEST(PbrtImport, LightsMapOntoPhotons) {
    const Json doc = import(R"(
LightSource "point" "point3 from" [1 2 3] "rgb I" [2 2 2] "float scale" [3]
LightSource "spot" "point3 from" [0 3 0] "point3 to" [0 0 0] "float coneangle" [40] "float conedeltaangle" [10] "blackbody I" [6500]
AttributeBegin
  Translate 0 0 1
  LightSource "distant" "point3 from" [0 1 0] "point3 to" [0 0 0] "rgb L" [5 5 5]
AttributeEnd
LightSource "infinite" "rgb L" [0.1 0.2 0.3]
)").document;
    const Json& l = doc["lights"];
    EXPECT_VEC3_NEAR(vec(l[0]["position"]), Vec3(1, 2, 3), 1e-6f);
    EXPECT_VEC3_NEAR(vec(l[0]["intensity"]), Vec3(6), 1e-5f);
    EXPECT_EQ(l[1]["cone_angle"], 40.0);
    EXPECT_EQ(l[1]["falloff_angle"], 30.0);
    EXPECT_NEAR(luminance(Color(vec(l[1]["intensity"]))), 1.0f, 1e-4f);  // blackbody: unit luminance
    EXPECT_VEC3_NEAR(vec(l[2]["direction"]), Vec3(0, -1, 0), 1e-6f);    // a translation leaves it
    EXPECT_VEC3_NEAR(vec(l[2]["irradiance"]), Vec3(5), 1e-6f);
    EXPECT_VEC3_NEAR(vec(l[3]["radiance"]), Vec3(0.1f, 0.2f, 0.3f), 1e-6f);
    // The area light's quad carries the emission.
    EXPECT_VEC3_NEAR(vec(doc["shapes"][0]["emission"]), Vec3(4), 1e-6f);
}

// "power" P as pbrt-v4 applies it (PointLight, SpotLight and DiffuseAreaLight::Create): the
// light times scale times P over the power it sends out at unit luminance, an "rgb"
// spectrum's own luminance kept: 4 pi for a point light, 2 pi ((1 - cos 30) + (cos 30 -
// cos 40) / 2) for a spot light of cone 40 and falloff from 30, and for an area light
// photon's emission_power, which divides by Y(emission x scale) pi A sides itself.
TEST(PbrtImport, LightPowerAsPbrtAppliesIt) {
    const ImportedScene s = import(R"(
LightSource "point" "rgb I" [2 1 0.5] "float scale" [3] "float power" [100]
LightSource "spot" "point3 to" [0 -1 0] "rgb I" [1 1 1] "float coneangle" [40] "float conedeltaangle" [10] "float power" [50]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [2 1 1] "float scale" [2] "float power" [10]
  Shape "trianglemesh" "point3 P" [0 3 0  1 3 0  1 3 1  0 3 1] "integer indices" [0 2 1  0 3 2]
AttributeEnd
)");
    const Json& l = s.document["lights"];
    const double pi = 3.14159265358979;
    EXPECT_VEC3_NEAR(vec(l[0]["intensity"]), Vec3(2, 1, 0.5f) * float(3 * 100 / (4 * pi)), 1e-4f);
    const double cos30 = std::cos(pi / 6), cos40 = std::cos(40 * pi / 180);
    EXPECT_VEC3_NEAR(vec(l[1]["intensity"]), Vec3(float(50 / (2 * pi * ((1 - cos30) + (cos30 - cos40) / 2)))), 1e-3f);
    const Json& lamp = s.document["shapes"][2];
    EXPECT_EQ(lamp["emission_scale"], 2.0);
    EXPECT_NEAR(lamp["emission_power"].get<double>(), 10 * 2 * luminance(Color(2, 1, 1)), 1e-4);
    // What the loaded lamp emits: L scale P / (pi A), A = 1, as pbrt-v4's.
    const SceneDescription d = loadImportedScene(s, scratch());
    EXPECT_VEC3_NEAR(d.shapes[2].emission, Vec3(2, 1, 1) * float(2 * 10 / pi), 1e-3f);
    EXPECT_TRUE(s.warnings.empty());
}

// A portal's corners are in world space, as pbrt-v4 reads them, whatever the light's
// transform (which turns its image); in order: the light comes in from the side of
// cross(p3 - p0, p1 - p0), pbrt-v4's convention, here a window in a ceiling at y = 2.
TEST(PbrtImport, InfinitePortalsAreInWorldSpace) {
    const Json doc = import(R"(
AttributeBegin
  Rotate 90 1 0 0
  LightSource "infinite" "rgb L" [1 1 1] "point3 portal" [-1 2 -1  1 2 -1  1 2 1  -1 2 1]
AttributeEnd
)").document;
    const Json& portal = doc["lights"][0]["portal"];
    ASSERT_EQ(portal.size(), 4u);
    EXPECT_VEC3_NEAR(vec(portal[0]), Vec3(-1, 2, -1), 1e-6f);
    EXPECT_VEC3_NEAR(vec(portal[2]), Vec3(1, 2, 1), 1e-6f);
    const Vec3 out = cross(vec(portal[3]) - vec(portal[0]), vec(portal[1]) - vec(portal[0]));
    EXPECT_GT(out.y, 0.0f);
    // A light behind each of two windows: both kept, and they add up.
    const ImportedScene two = import(R"(
LightSource "infinite" "rgb L" [1 1 1] "point3 portal" [-1 2 -1  1 2 -1  1 2 1  -1 2 1]
LightSource "infinite" "rgb L" [1 1 1] "point3 portal" [2 0 -1  2 0 1  2 1 1  2 1 -1]
Shape "sphere"
)");
    EXPECT_EQ(loadImportedScene(two, scratch()).lights.size(), 2u);
    const std::string head = "Camera \"perspective\"\nWorldBegin\n";
    EXPECT_STREQ(importError(head + "LightSource \"infinite\" \"point3 portal\" [0 0 0  1 0 0  1 1 0]\n").what(),
                 "bad.pbrt:3: infinite: \"portal\" must be 4 points, not 9 numbers");
    EXPECT_STREQ(importError(head + "LightSource \"infinite\" \"point3 portal\" [0 0 0  1 0 0  2 1 0  0 1 0]\n").what(),
                 "bad.pbrt:3: infinite: \"portal\" must be a rectangle: the third corner is not opposite the first");
}

// "illuminance" as pbrt-v4 applies it: the distant light's irradiance and the uniform
// infinite light's pi L become it (times "scale"), an RGB's colour kept; an image's is
// measured when the image is loaded.
TEST(PbrtImport, IlluminanceSetsTheLightsLevel) {
    const Json doc = import(R"(
LightSource "distant" "rgb L" [1 0.5 0.25] "float scale" [2] "float illuminance" [3]
LightSource "infinite" "rgb L" [0.5 0.5 0.5] "float illuminance" [10]
LightSource "infinite" "string filename" "sky.exr" "float illuminance" [7]
)").document;
    const Json& l = doc["lights"];
    EXPECT_VEC3_NEAR(vec(l[0]["irradiance"]), Vec3(6, 3, 1.5f), 1e-5f);
    EXPECT_VEC3_NEAR(vec(l[1]["radiance"]), Vec3(5 / kPi), 1e-5f);
    EXPECT_EQ(l[2]["illuminance"], 7.0);
}

// An infinite light's CTM: a rotation becomes "rotate", a mirror image (Bitterli's teapot
// flips x) "matrix" with the linear part as written; a scale is refused.
TEST(PbrtImport, InfiniteLightsFrame) {
    const Json l = import(R"(
AttributeBegin
  Rotate 90 0 1 0
  LightSource "infinite" "string filename" "sky.exr"
AttributeEnd
AttributeBegin
  Transform [-0.386527 0 0.922278 0  -0.922278 0 -0.386527 0  0 1 0 0  0 0 0 1]
  LightSource "infinite" "string filename" "sky.exr"
AttributeEnd
)").document["lights"];
    EXPECT_EQ(l[0]["rotate"]["angle"].get<double>(), 90.0);
    EXPECT_FALSE(l[0].contains("matrix"));
    ASSERT_TRUE(l[1].contains("matrix"));
    EXPECT_FALSE(l[1].contains("rotate"));
    // pbrt's Transform lists columns; photon's matrix is row-major.
    const std::vector<double> expected{-0.386527, -0.922278, 0, 0, 0, 0, 1, 0, 0.922278, -0.386527, 0, 0, 0, 0, 0, 1};
    for (size_t i = 0; i < 16; ++i) EXPECT_NEAR(l[1]["matrix"][i].get<double>(), expected[i], 1e-6) << i;
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nScale 2 1 1\nLightSource \"infinite\" \"string filename\" \"sky.exr\"\n").what(),
                 "bad.pbrt:4: infinite: the light's transform must be a rotation or a mirror image (it scales or shears)");
}


// pbrt-v4's goniometric light: a point light at the light frame's origin, the image's square
// centred on the frame's +y (pbrt-v4 swaps y and z), its "power" taken over the image's mean.
// Loaded, it shines I times each texel into its quadrant: the frame's (x, y, z) is the
// square's (x, z, y), x to the right and its y up the image.
TEST(PbrtImport, AGoniometricLightIsAPointLightWithAProfile) {
    // 2 x 2 texels, grey: 1, 2 on the top row, 3, 6 below (equal-area: the four quadrants).
    test::writeImage<float>(scratch() / "profile.exr", 2, 2, 3, {1, 1, 1, 2, 2, 2, 3, 3, 3, 6, 6, 6});
    const ImportedScene s = import(R"(
AttributeBegin
  Translate 1 2 3
  Rotate 90 1 0 0
  LightSource "goniometric" "string filename" "profile.exr" "rgb I" [2 2 2] "float scale" 0.5
AttributeEnd
LightSource "goniometric" "string filename" "profile.exr" "float power" 30
)");
    const Json& l = s.document["lights"];
    EXPECT_EQ(l[0]["type"], "point");
    EXPECT_VEC3_NEAR(vec(l[0]["position"]), Vec3(1, 2, 3), 1e-6f);
    EXPECT_VEC3_NEAR(vec(l[0]["intensity"]), Vec3(1), 1e-6f);
    EXPECT_EQ(l[0]["image"], "profile.exr");
    EXPECT_EQ(l[0]["layout"], "equal_area");
    // Rotate 90 about x takes the frame's +y to +z: the square's centre looks along world +z.
    const SceneDescription d = loadImportedScene(s, scratch());
    const std::unique_ptr<Light> light = makePointLight(d.lights[0]);
    const Color centre = light->emittedDensity({0, 0, 1});
    EXPECT_TRUE(centre.x > 0.99f && centre.x < 6.01f) << centre.x;  // one of the texels around the centre
    // World (0.3, 0.3, 1) is the frame's (0.3, 1, -0.3): the square's x > 0, y < 0, the
    // top right texel (2); world (-0.3, -0.3, 1) the bottom left (3).
    EXPECT_NEAR(light->emittedDensity(normalize(Vec3(0.3f, 0.3f, 1))).x, 2.0f, 1e-5f);
    EXPECT_NEAR(light->emittedDensity(normalize(Vec3(-0.3f, -0.3f, 1))).x, 3.0f, 1e-5f);
    // power 30 over 4 pi times the texels' mean (3): I = 30 / (12 pi).
    EXPECT_VEC3_NEAR(vec(l[1]["intensity"]), Vec3(float(30 / (12 * kPi))), 1e-6f);
    EXPECT_NEAR(makePointLight(d.lights[1])->power().y, 30.0f, 1e-3f);
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nLightSource \"goniometric\"\n").what(),
                 "bad.pbrt:3: goniometric: needs a \"filename\" (the image it sends out)");
}

// pbrt-v4's projection light: the image along the light frame's +z, its top toward the
// frame's +y; "power" over A times the texels' mean luminance x cos^3 (pbrt-v4's sum).
TEST(PbrtImport, AProjectionLightIsASlideProjector) {
    test::writeImage<float>(scratch() / "slide.exr", 2, 1, 3, {1, 0, 0, 0, 0, 1});
    const ImportedScene s = import(R"(
AttributeBegin
  Translate 0 2 0
  Rotate 90 1 0 0
  LightSource "projection" "string filename" "slide.exr" "float fov" 40 "float scale" 3
AttributeEnd
LightSource "projection" "string filename" "slide.exr" "float power" 10
)");
    const Json& l = s.document["lights"];
    EXPECT_EQ(l[0]["type"], "projection");
    EXPECT_VEC3_NEAR(vec(l[0]["position"]), Vec3(0, 2, 0), 1e-6f);
    EXPECT_VEC3_NEAR(vec(l[0]["intensity"]), Vec3(3), 1e-6f);
    EXPECT_EQ(l[0]["fov"], 40.0);
    const SceneDescription d = loadImportedScene(s, scratch());
    const std::unique_ptr<Light> light = makeProjectionLight(d.lights[0]);
    // Rotate 90 about x takes the frame's +z to world -y: it projects down, the frame's +x
    // (the image's left to right) along world +x: red to -x, blue to +x.
    EXPECT_NEAR(light->emittedDensity(normalize(Vec3(-0.1f, -1, 0))).x, 3.0f, 1e-5f);
    EXPECT_NEAR(light->emittedDensity(normalize(Vec3(0.1f, -1, 0))).z, 3.0f, 1e-5f);
    EXPECT_TRUE(isBlack(light->emittedDensity(normalize(Vec3(0.1f, 1, 0)))));
    // power 10: 2 x 1 texels at fov 90, A = 4 x 2, centres at (+-1, 0), cos^3 = 2^-1.5; the
    // mean luminance x cos^3 (0.2126 + 0.0722) / 2 x 2^-1.5.
    const double k = 8 * (0.2126 + 0.0722) / 2 * std::pow(2.0, -1.5);
    EXPECT_NEAR(l[1]["intensity"][0].get<double>(), 10 / k, 1e-4 * 10 / k);
}

// pbrt-v4 makes an area light of constant alpha 0 invisible: no ray meets it, and it lights
// in full through light samples (pbrt-v4-scenes' kroken: a sphere of radius 90 with "float
// alpha" 0; sportscar-area-lights' panels).
TEST(PbrtImport, AnAreaLightOfAlphaZeroIsAnInvisibleOne) {
    const std::string light = "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [9 9 9]\n";
    const ImportedScene s = import(light + "Shape \"sphere\" \"float radius\" 90 \"float alpha\" 0\nAttributeEnd\n");
    EXPECT_TRUE(s.warnings.empty());
    const Json& sphere = s.document["shapes"][2];
    EXPECT_EQ(sphere["invisible"], true);
    EXPECT_EQ(sphere["emission"], Json({9, 9, 9}));
    EXPECT_FALSE(sphere.contains("alpha"));
    // Cut away in part, it would be seen and light in part: refused, or whole when lenient.
    const std::string half = kHeader + light + "Shape \"sphere\" \"float alpha\" 0.5\nAttributeEnd\n";
    EXPECT_STREQ(importError(half).what(),
                 "bad.pbrt:14: Shape \"sphere\": an area light cut away in part (alpha below 1) is not supported");
    const ImportedScene whole = importPbrt(writeScene("whole.pbrt", half), true);
    const Json& lenient = whole.document["shapes"][2];
    EXPECT_EQ(lenient["type"], "sphere");
    EXPECT_FALSE(lenient.contains("alpha"));
    EXPECT_FALSE(lenient.contains("invisible"));
    EXPECT_EQ(lenient["emission"], Json({9, 9, 9}));
}

// pbrt-v4 keeps any 4x4 matrix and turns directions by its upper 3x3: pbrt-v4-scenes'
// sssdragon orients its sky by a ConcatTransform whose last row is 0 0 8.87 1.
TEST(PbrtImport, AProjectiveTransformTurnsDirectionsButRefusesPoints) {
    const std::string projective = "ConcatTransform [0 0 1 0  0 1 0 0  -1 0 0 8.87  0 0 0 1]\n";
    const ImportedScene s = import("AttributeBegin\n" + projective + "Rotate 90 0 1 0\n" +
                                   "LightSource \"distant\" \"point3 from\" [0 0 0] \"point3 to\" [0 0 1]\nAttributeEnd\n");
    // The rotation turns +z to +x, then the matrix's 3x3 +x to +z.
    const Vec3 direction = vec(s.document["lights"].back()["direction"]);
    EXPECT_NEAR(direction.x, 0, 1e-6);
    EXPECT_NEAR(direction.y, 0, 1e-6);
    EXPECT_NEAR(direction.z, 1, 1e-6);
    EXPECT_STREQ(importError(kHeader + projective + "Shape \"sphere\"\n").what(),
                 "bad.pbrt:13: Shape \"sphere\": the transform is projective (its last row is 0 0 8.87 1), which "
                 "photon applies to directions only (infinite and distant lights)");
    // Transform replaces it with an affine matrix again.
    EXPECT_EQ(import(projective + "Transform [1 0 0 0  0 1 0 0  0 0 1 0  0 0 2 1]\nShape \"sphere\"\n")
                  .document["shapes"][2]["transform"],
              Json({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 2, 0, 0, 0, 1}}}));
}


// pbrt-v4's film sensor multiplies the image by exposure time x ISO / 100 (PixelSensor's
// imaging ratio; the exposure time is the camera's shutterclose - shutteropen): the import
// scales every light by it, which scales the image the same.
TEST(PbrtImport, TheFilmsIsoAndTheShutterScaleTheImageThroughTheLights) {
    const std::string scene = R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30] "float shutteropen" 0.25 "float shutterclose" 0.75
Film "rgb" "integer xresolution" [64] "integer yresolution" [32] "float iso" 400
WorldBegin
LightSource "point" "rgb I" [1 2 3] "float scale" 3
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4] "float power" 10
  Shape "sphere" "float radius" 0.1
AttributeEnd
Shape "trianglemesh" "point3 P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5] "integer indices" [0 2 1 0 3 2]
)";
    const ImportedScene s = importPbrt(writeScene("iso.pbrt", scene));
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();  // iso and the shutter are read
    const Json& lights = s.document["lights"];
    // Ratio 0.5 x 400 / 100 = 2.
    EXPECT_EQ(lights[0]["intensity"], Json({6, 12, 18}));
    EXPECT_EQ(lights[1]["radiance"], Json({1, 1, 1}));
    const Json& lamp = s.document["shapes"][0];
    EXPECT_EQ(lamp["emission_scale"], 2);
    EXPECT_NEAR(lamp["emission_power"].get<double>(), 20 * 4, 1e-4);  // P x scale x Y(L)
    std::string closedFirst = scene;
    closedFirst.replace(closedFirst.find("0.25"), 4, "0.85");
    EXPECT_STREQ(importError(closedFirst).what(), "bad.pbrt:3: Camera: \"shutterclose\" must come after \"shutteropen\"");
}

}  // namespace
}  // namespace photon
