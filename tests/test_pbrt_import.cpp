// The pbrt-v4 importer: pbrt's conventions (transform order, the camera's left-handed
// space and fov on the shorter axis, orientation from normals and ReverseOrientation) and
// each directive's mapping onto photon's scene, against values worked out by hand; errors
// and warnings with their file:line; and photon-convert's JSON rendering the same image as
// the file it came from.
#include <gtest/gtest.h>
#include <unistd.h>
#include <cmath>
#include <fstream>
#include <photon/errors.h>
#include <photon/render.h>
#include <photon/scene_convert.h>
#include "import/pbrt/pbrt_import.h"
#include "pbrt_import_fixture.h"
#include "materials/fresnel.h"
#include "scene/ply_mesh.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon {
namespace {

using namespace test::pbrt_import;

TEST(PbrtImport, CameraFromLookAtIsLeftHandedWithFovOnTheShorterAxis) {
    const Json cam = import("").document["camera"];
    EXPECT_VEC3_NEAR(vec(cam["position"]), Vec3(0, 1, 5), 1e-5f);
    EXPECT_VEC3_NEAR(vec(cam["look_at"]) - vec(cam["position"]), Vec3(0, 0, -1), 1e-5f);
    EXPECT_VEC3_NEAR(vec(cam["up"]), Vec3(0, 1, 0), 1e-5f);
    EXPECT_NEAR(cam["fov"].get<double>(), 30, 1e-4);  // landscape: the shorter axis is the vertical one
    EXPECT_EQ(cam["resolution"], Json::parse("[64, 32]"));
    // pbrt's LookAt puts the image's right at up x forward: -x here, mirrored from photon's.
    EXPECT_EQ(cam["handedness"], "left");
    // A portrait film: the fov is the horizontal one, so the vertical is wider.
    const Json portrait = importPbrt(writeScene("portrait.pbrt", R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30]
Film "rgb" "integer xresolution" [50] "integer yresolution" [100]
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Shape "sphere")")).document["camera"];
    EXPECT_NEAR(portrait["fov"].get<double>(), 2 * std::atan(2 * std::tan(15 * kPi / 180)) * 180 / kPi, 1e-4);
}

// pbrt-v4's light samplers: "power" stays power, "bvh" (its default) and the others become
// photon's spatial sampler, the one that weighs lights by their bounds at the point.
TEST(PbrtImport, IntegratorsLightSamplerMapsOntoPhotons) {
    auto lightSampler = [](const std::string& value) {
        const Json render = importPbrt(writeScene("sampler-" + value + ".pbrt", R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30]
Integrator "path" "string lightsampler" ")" + value + R"("
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Shape "sphere")")).document["render"];
        return render["light_sampler"].get<std::string>();
    };
    EXPECT_EQ(lightSampler("power"), "power");
    EXPECT_EQ(lightSampler("bvh"), "spatial");
    EXPECT_EQ(lightSampler("uniform"), "spatial");
}

// pbrt-v4's SPPM integrator: its photons per iteration (one a pixel of the film where the
// file gives none or -1, as pbrt-v4's SPPMIntegrator takes them), its initial radius, seed
// and depth.
TEST(PbrtImport, SppmIntegratorKeepsItsParameters) {
    auto renderOf = [](const std::string& integrator) {
        return importPbrt(writeScene("sppm.pbrt", R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30]
)" + integrator + R"(
Film "rgb" "integer xresolution" [40] "integer yresolution" [30]
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Shape "sphere")")).document["render"];
    };
    const Json given = renderOf(R"(Integrator "sppm" "integer photonsperiteration" [5000] "float radius" [0.25]
    "integer seed" [7] "integer maxdepth" [9])");
    EXPECT_EQ(given["integrator"], "sppm");
    EXPECT_EQ(given["photons_per_pass"], 5000);
    EXPECT_EQ(given["initial_radius"], 0.25);
    EXPECT_EQ(given["seed"], 7);
    EXPECT_EQ(given["max_depth"], 9);
    EXPECT_EQ(renderOf(R"(Integrator "sppm")")["photons_per_pass"], 40 * 30);
    EXPECT_EQ(renderOf(R"(Integrator "sppm" "integer photonsperiteration" [-1])")["photons_per_pass"], 40 * 30);
    EXPECT_FALSE(renderOf(R"(Integrator "path")").contains("photons_per_pass"));
}

// pbrt-v4's samplers: "independent" stays independent; the stratifying ones (zsobol, its
// default, sobol, halton, pmj02bn, stratified...) become photon's Sobol passes; the
// sample count becomes the passes.
TEST(PbrtImport, SamplerMapsOntoPhotonsSamplerAndPasses) {
    auto renderOf = [](const std::string& name, const std::string& directive) {
        return importPbrt(writeScene("pixel-sampler-" + name + ".pbrt", R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30]
)" + directive + R"(
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Shape "sphere")")).document["render"];
    };
    const Json independent = renderOf("independent", R"(Sampler "independent" "integer pixelsamples" [8])");
    EXPECT_EQ(independent["sampler"], "independent");
    EXPECT_EQ(independent["passes"], 8);
    EXPECT_EQ(renderOf("zsobol", R"(Sampler "zsobol")")["sampler"], "sobol");
    EXPECT_EQ(renderOf("halton", R"(Sampler "halton")")["sampler"], "sobol");
    EXPECT_EQ(renderOf("pmj02bn", R"(Sampler "pmj02bn")")["sampler"], "sobol");
    // pbrt-v4's sample counts where none is given, and the stratified sampler's x times y.
    EXPECT_EQ(renderOf("independent-default", R"(Sampler "independent")")["passes"], 4);
    EXPECT_EQ(renderOf("zsobol-default", R"(Sampler "zsobol")")["passes"], 16);
    EXPECT_EQ(renderOf("stratified", R"(Sampler "stratified" "integer xsamples" [2] "integer ysamples" [8] "bool jitter" false)")["passes"], 16);
    EXPECT_EQ(renderOf("stratified-default", R"(Sampler "stratified")")["passes"], 16);
    EXPECT_EQ(renderOf("stratified-x", R"(Sampler "stratified" "integer xsamples" [3])")["passes"], 12);
    // None: pbrt-v4's default, zsobol, and photon's own default alike; pbrt-v4's 16 samples
    // a pixel, and its volpath's maxdepth of 5 where there is no Integrator either.
    const Json none = renderOf("none", "");
    EXPECT_FALSE(none.contains("sampler"));
    EXPECT_EQ(none["passes"], 16);
    EXPECT_EQ(none["max_depth"], 5);
}

// PixelFilter onto camera.filter, with pbrt-v4's defaults (a Gaussian when there is none).
TEST(PbrtImport, PixelFilterMapsOntoTheCamerasFilter) {
    auto filterOf = [](const std::string& name, const std::string& directive) {
        const ImportedScene s = importPbrt(writeScene("filter-" + name + ".pbrt", R"(
LookAt 0 1 5  0 1 0  0 1 0
Camera "perspective" "float fov" [30]
)" + directive + R"(
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Shape "sphere")"));
        return std::make_pair(s.document["camera"]["filter"], s.warnings);
    };
    EXPECT_EQ(filterOf("none", "").first, Json::parse(R"({"type": "gaussian", "radius": 1.5, "sigma": 0.5})"));
    EXPECT_EQ(filterOf("triangle", R"(PixelFilter "triangle" "float xradius" [1] "float yradius" [1])").first,
              Json::parse(R"({"type": "triangle", "radius": [1.0, 1.0]})"));
    EXPECT_EQ(filterOf("box", R"(PixelFilter "box")").first, Json::parse(R"({"type": "box", "radius": [0.5, 0.5]})"));
    EXPECT_EQ(filterOf("gaussian", R"(PixelFilter "gaussian" "float sigma" [0.3] "float xradius" [2])").first,
              Json::parse(R"({"type": "gaussian", "radius": [2.0, 1.5], "sigma": 0.3})"));
    const auto [sinc, warnings] = filterOf("sinc", R"(PixelFilter "sinc" "float tau" [2])");
    EXPECT_EQ(sinc, Json::parse(R"({"type": "lanczos", "radius": [4.0, 4.0], "tau": 2.0})"));
    ASSERT_FALSE(warnings.empty());
    EXPECT_EQ(warnings.front(),
              "filter-sinc.pbrt:4: PixelFilter \"sinc\": its negative lobes are left out (photon's pixel estimates are "
              "not negative)");
    const auto [mitchell, none] = filterOf("mitchell", R"(PixelFilter "mitchell" "float B" [0.5] "float C" [0.25])");
    EXPECT_EQ(mitchell, Json::parse(R"({"type": "mitchell", "radius": [2.0, 2.0], "b": 0.5, "c": 0.25})"));
    EXPECT_EQ(importError(R"(Camera "perspective"
PixelFilter "gaussian" "float xradius" [20]
WorldBegin)")
                  .what(),
              std::string("bad.pbrt:2: PixelFilter: xradius and yradius must be in [0.05, 8]"));
    EXPECT_EQ(importError(R"(Camera "perspective"
PixelFilter "mitchell" "float B" [2]
WorldBegin)")
                  .what(),
              std::string("bad.pbrt:2: PixelFilter: B must be in [0, 1]"));
}

TEST(PbrtImport, CameraSeesTheImageTheRightWayRound) {
    // A red quad on the left of the view (x < 0 in a world whose camera x axis is -x ...)
    // pbrt: with this LookAt, world +x is the image's left. The red quad at x = +1 must
    // therefore show in the left half of the image.
    ImportedScene s = importPbrt(writeScene("sides.pbrt", R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
WorldBegin
LightSource "distant" "point3 from" [0 0 1] "point3 to" [0 0 0] "rgb L" [3 3 3]
Material "diffuse" "rgb reflectance" [0.8 0 0]
Shape "trianglemesh" "point3 P" [0.2 -1 0  1.5 -1 0  1.5 1 0  0.2 1 0] "integer indices" [0 1 2 0 2 3])"));
    SceneDescription d = loadImportedScene(s, scratch(), {{"render.integrator", "path"}, {"render.passes", "4"}});
    Image image = test::renderImage(std::move(d));
    EXPECT_GT(test::meanOver(image, 0, 0, 8, 16).x, 0.1f);
    EXPECT_EQ(test::meanOver(image, 8, 0, 16, 16).x, 0.0f);
}

TEST(PbrtImport, TransformsComposeInPbrtsOrder) {
    // Translate then Scale: the scale applies first (pbrt post-multiplies the CTM).
    ImportedScene s = import(R"(
AttributeBegin
  Translate 1 2 3
  Scale 2 2 2
  Shape "trianglemesh" "point3 P" [0 0 0  1 0 0  0 1 0]
AttributeEnd
AttributeBegin
  Transform [0 1 0 0  -1 0 0 0  0 0 1 0  5 0 0 1]
  Shape "trianglemesh" "point3 P" [0 0 0  1 0 0  0 1 0]
AttributeEnd)");
    SceneDescription d = loadImportedScene(s, scratch());
    const TriangleMesh& a = d.shapes[2].mesh;
    EXPECT_VEC3_NEAR(a.positions[1], Vec3(3, 2, 3), 1e-5f);  // 2 * (1, 0, 0) + (1, 2, 3)
    const TriangleMesh& b = d.shapes[3].mesh;
    // Columns (0 1 0), (-1 0 0), (0 0 1), translation (5 0 0): x maps to +y.
    EXPECT_VEC3_NEAR(b.positions[1], Vec3(5, 1, 0), 1e-5f);
    EXPECT_VEC3_NEAR(b.positions[2], Vec3(4, 0, 0), 1e-5f);
}

TEST(PbrtImport, OrientationFollowsNormalsAndReverseOrientation) {
    // Wound to face -y, with normals +y: pbrt's surface faces the normals' side.
    ImportedScene s = import(R"(
Shape "trianglemesh" "point3 P" [0 1 0  1 1 0  0 1 1] "normal N" [0 1 0  0 1 0  0 1 0]
Shape "trianglemesh" "point3 P" [0 1 0  1 1 0  0 1 1]
ReverseOrientation
Shape "trianglemesh" "point3 P" [0 1 0  1 1 0  0 1 1])");
    SceneDescription d = loadImportedScene(s, scratch());
    EXPECT_VEC3_NEAR(d.shapes[2].mesh.faceNormal(0), Vec3(0, 1, 0), 1e-6f);
    const Vec3 plain = d.shapes[3].mesh.faceNormal(0), reversed = d.shapes[4].mesh.faceNormal(0);
    EXPECT_VEC3_NEAR(plain, Vec3(0, -1, 0), 1e-6f);  // (1,0,0) x (0,0,1) = (0,-1,0)
    EXPECT_VEC3_NEAR(reversed, Vec3(0, 1, 0), 1e-6f);
}

TEST(PbrtImport, MaterialsMapOntoPhotons) {
    const ImportedScene scene = import(R"(
MakeNamedMaterial "gold" "string type" "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k"
  "float roughness" [0.04]
MakeNamedMaterial "plastic" "string type" "coateddiffuse" "rgb reflectance" [0.2 0.3 0.4]
  "float roughness" [0.01] "bool remaproughness" false
MakeNamedMaterial "glass" "string type" "dielectric" "spectrum eta" "glass-BK7"
MakeNamedMaterial "pane" "string type" "thindielectric" "float eta" [1.4]
MakeNamedMaterial "sheet" "string type" "diffusetransmission" "rgb transmittance" [0.5 0.5 0.5] "float scale" [0.5]
MakeNamedMaterial "both" "string type" "mix" "string materials" ["gold" "plastic"] "float amount" [0.25]
Texture "bumps" "float" "checkerboard" "float tex1" [0.01] "float tex2" [0.2]
MakeNamedMaterial "varnish" "string type" "coateddiffuse" "texture roughness" "bumps"
)");
    const Json& m = scene.document["materials"];
    EXPECT_NO_THROW(loadImportedScene(scene, scratch()));
    // A roughness map on coateddiffuse keeps pbrt's meaning (remaproughness, true by default).
    EXPECT_EQ(m["varnish"]["roughness"]["type"], "checkerboard");
    EXPECT_EQ(m["varnish"]["remap_roughness"], true);
    EXPECT_EQ(m["gold"], Json::parse(R"({"type": "conductor", "eta": "metal-Au-eta", "k": "metal-Au-k",
        "uroughness": 0.04, "vroughness": 0.04, "remap_roughness": true})"));
    // alpha = 0.01 (no remap); photon's perceptual roughness is sqrt(alpha).
    EXPECT_EQ(m["plastic"]["type"], "coated_diffuse");
    EXPECT_NEAR(m["plastic"]["roughness"].get<double>(), 0.1, 1e-9);
    EXPECT_NEAR(m["plastic"]["ior"].get<double>(), 1.5, 1e-9);
    EXPECT_NEAR(m["glass"]["ior"].get<double>(), 1.5168, 1e-4);
    EXPECT_EQ(m["pane"]["thin"], true);
    EXPECT_NEAR(m["sheet"]["transmittance"][0].get<double>(), 0.25, 1e-6);
    EXPECT_NEAR(m["sheet"]["reflectance"][0].get<double>(), 0.125, 1e-6);
    EXPECT_EQ(m["both"], Json::parse(R"({"type": "mix", "materials": ["gold", "plastic"], "amount": 0.25})"));
}

// An imagemap's "encoding" is kept: "linear" (the image read without the sRGB curve) and
// "gamma g" (read as stored to the power g). Where it is not given, pbrt-v4 reads a PNG as
// sRGB and any other file as linear (a JPEG too); a TGA stays sRGB, as pbrt-v3 read it and
// as scenes pbrt-v4's --upgrade carried over from it (without an encoding) were made.
TEST(PbrtImport, ImagemapEncoding) {
    const ImportedScene s = import(R"(
Texture "plain" "spectrum" "imagemap" "string filename" "a.png" "string encoding" "linear"
Texture "curved" "spectrum" "imagemap" "string filename" "a.png" "string encoding" "gamma 2.2"
Texture "photo" "spectrum" "imagemap" "string filename" "b.JPG"
Texture "png" "spectrum" "imagemap" "string filename" "c.png"
Texture "tga" "spectrum" "imagemap" "string filename" "d.TGA"
Texture "tgalinear" "spectrum" "imagemap" "string filename" "d.tga" "string encoding" "linear"
MakeNamedMaterial "m" "string type" "diffuse" "texture reflectance" "plain"
MakeNamedMaterial "n" "string type" "diffuse" "texture reflectance" "curved"
MakeNamedMaterial "o" "string type" "diffuse" "texture reflectance" "photo"
MakeNamedMaterial "p" "string type" "diffuse" "texture reflectance" "png"
MakeNamedMaterial "q" "string type" "diffuse" "texture reflectance" "tga"
MakeNamedMaterial "r" "string type" "diffuse" "texture reflectance" "tgalinear"
)");
    EXPECT_EQ(s.document["materials"]["m"]["albedo"], Json::parse(R"({"type": "image", "file": "a.png", "encoding": "linear"})"));
    EXPECT_EQ(s.document["materials"]["n"]["albedo"],
              Json::parse(R"({"type": "image", "file": "a.png", "encoding": "gamma", "gamma": 2.2})"));
    EXPECT_EQ(s.document["materials"]["o"]["albedo"], Json::parse(R"({"type": "image", "file": "b.JPG", "encoding": "linear"})"));
    EXPECT_EQ(s.document["materials"]["p"]["albedo"], Json::parse(R"({"type": "image", "file": "c.png"})"));
    EXPECT_EQ(s.document["materials"]["q"]["albedo"], Json::parse(R"({"type": "image", "file": "d.TGA"})"));
    EXPECT_EQ(s.document["materials"]["r"]["albedo"], Json::parse(R"({"type": "image", "file": "d.tga", "encoding": "linear"})"));
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_STREQ(importError(kHeader + "Texture \"odd\" \"spectrum\" \"imagemap\" \"string filename\" \"a.png\" "
                                       "\"string encoding\" \"log\"\n").what(),
                 "bad.pbrt:12: Texture \"odd\": encoding \"log\" is not sRGB, linear or \"gamma g\" (0 < g < 10)");
}

// An imagemap's "wrap" (clamp, black) and "invert" are the image texture's; invert with a
// scale other than 1 is refused (pbrt inverts the scaled value).
TEST(PbrtImport, ImagemapWrapAndInvert) {
    const ImportedScene s = import(R"(
Texture "edge" "spectrum" "imagemap" "string filename" "a.png" "string wrap" "clamp" "bool invert" true
Texture "dark" "float" "imagemap" "string filename" "a.png" "string wrap" "black"
MakeNamedMaterial "m" "string type" "diffuse" "texture reflectance" "edge"
MakeNamedMaterial "n" "string type" "conductor" "texture roughness" "dark"
)");
    EXPECT_EQ(s.document["materials"]["m"]["albedo"],
              Json::parse(R"({"type": "image", "file": "a.png", "wrap": "clamp", "invert": true})"));
    EXPECT_EQ(s.document["materials"]["n"]["uroughness"],
              Json::parse(R"({"type": "image", "file": "a.png", "channel": "r", "encoding": "srgb", "wrap": "black"})"));
    EXPECT_STREQ(importError(kHeader + "Texture \"i\" \"spectrum\" \"imagemap\" \"string filename\" \"a.png\" "
                                       "\"bool invert\" true \"float scale\" 2\n").what(),
                 "bad.pbrt:12: Texture \"i\": \"invert\" with a \"scale\" other than 1 is not supported");
}

// coatedconductor becomes photon's coated_conductor: the interface's index and roughness
// (alpha = sqrt(0.01) remapped, so photon's perceptual roughness is sqrt(0.1)), the metal's
// index as pbrt gives it (the material divides it by the coat's) and roughness; a constant
// reflectance becomes pbrt-v4's index for it, eta 1 and k = 2 sqrt(r) / sqrt(1 - r), whose
// Fresnel at normal incidence is r again.
TEST(PbrtImport, CoatedConductorAndReflectanceIndex) {
    const ImportedScene s = import(R"(
MakeNamedMaterial "paint" "string type" "coatedconductor" "float interface.eta" [1.6]
  "float interface.roughness" [0.01] "spectrum conductor.eta" "metal-Al-eta" "spectrum conductor.k" "metal-Al-k"
  "float conductor.roughness" [0.09] "float thickness" [0.02]
MakeNamedMaterial "smooth" "string type" "coatedconductor" "rgb reflectance" [0.9 0.5 0.2]
MakeNamedMaterial "plain" "string type" "conductor" "rgb reflectance" [0.64 0.25 0]
)");
    const Json& m = s.document["materials"];
    EXPECT_EQ(m["paint"]["type"], "coated_conductor");
    EXPECT_NEAR(m["paint"]["ior"].get<double>(), 1.6, 1e-6);  // read as a float
    EXPECT_NEAR(m["paint"]["roughness"].get<double>(), std::sqrt(0.1), 1e-6);
    EXPECT_EQ(m["paint"]["conductor"], Json::parse(R"({"eta": "metal-Al-eta", "k": "metal-Al-k",
        "uroughness": 0.09, "vroughness": 0.09, "remap_roughness": true})"));
    EXPECT_EQ(m["smooth"]["ior"], 1.5);
    EXPECT_FALSE(m["smooth"].contains("roughness"));
    EXPECT_EQ(m["smooth"]["conductor"]["roughness"], 0);
    EXPECT_EQ(m["plain"]["type"], "conductor");
    EXPECT_EQ(m["plain"]["eta"], Json::parse("[1, 1, 1]"));
    const double r[3] = {0.64, 0.25, 0};
    for (int c = 0; c < 3; ++c) {
        const double k = m["plain"]["k"][c].get<double>();
        EXPECT_NEAR(k, 2 * std::sqrt(r[c]) / std::sqrt(1 - r[c]), 1e-6);  // from a float reflectance
        EXPECT_NEAR(fresnelConductor(1.0f, 1.0f, float(k)), r[c], 1e-6);
    }
    // Nothing of the coat is left out, so nothing is warned.
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

// pbrt-v4's "scale" texture takes a float texture (or number) as its scale for either kind:
// a spectrum texture's becomes the grey of it.
TEST(PbrtImport, ScaleTexturesTakeAFloatScale) {
    const ImportedScene s = import(R"(
Texture "c" "spectrum" "checkerboard" "rgb tex1" [1 0 0] "rgb tex2" [0 0 1]
Texture "m" "float" "checkerboard" "float tex1" 0.2 "float tex2" 0.8
Texture "byNumber" "spectrum" "scale" "texture tex" "c" "float scale" 0.5
Texture "byTexture" "spectrum" "scale" "texture tex" "c" "texture scale" "m"
MakeNamedMaterial "n" "string type" "diffuse" "texture reflectance" "byNumber"
MakeNamedMaterial "t" "string type" "diffuse" "texture reflectance" "byTexture"
)");
    const Json checker = Json::parse(R"({"type": "checkerboard", "even": [1, 0, 0], "odd": [0, 0, 1]})");
    EXPECT_EQ(s.document["materials"]["n"]["albedo"], (Json{{"type", "product"}, {"a", checker}, {"b", {0.5, 0.5, 0.5}}}));
    EXPECT_EQ(s.document["materials"]["t"]["albedo"],
              (Json{{"type", "product"},
                    {"a", checker},
                    {"b", Json::parse(R"({"type": "checkerboard", "even": [0.2, 0.2, 0.2], "odd": [0.8, 0.8, 0.8]})")}}));
}

// A coat thicker than photon's thin coat can stand for is warned of (pbrt-v4 attenuates light
// crossing it by exp(-thickness / cos)).
TEST(PbrtImport, ThickCoatsAreWarnedOf) {
    const ImportedScene s = import(R"(
MakeNamedMaterial "thick" "string type" "coateddiffuse" "rgb reflectance" [0.5 0.5 0.5] "float thickness" [0.5]
)");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("coateddiffuse: \"thickness\" 0.5"), std::string::npos) << s.warnings[0];
}

// A frameaspectratio other than the film's would stretch the image: refused. The film's own
// is accepted.
TEST(PbrtImport, FrameAspectRatioOtherThanTheFilmsIsRefused) {
    auto scene = [](const std::string& ratio) {
        return "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float frameaspectratio\" [" + ratio +
               "]\nFilm \"rgb\" \"integer xresolution\" [200] \"integer yresolution\" [100]\nWorldBegin\n"
               "Shape \"sphere\"\n";
    };
    EXPECT_STREQ(importError(scene("1")).what(),
                 "bad.pbrt:2: Camera: a frameaspectratio other than the film's (200 / 100) stretches the image, which is "
                 "not supported");
    EXPECT_NO_THROW(importPbrt(writeScene("frame-aspect.pbrt", scene("2"))));
}

// An orthographic camera: the screen [-aspect, aspect] x [-1, 1] (the shorter axis spans
// 2) in camera space, which the camera transform scales: under Scale 0.5 (world to camera)
// the view is 4 units high; a lens is refused.
TEST(PbrtImport, OrthographicCamera) {
    const Json camera = importPbrt(writeScene("ortho.pbrt", R"(Scale 0.5 0.5 0.5
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic"
Film "rgb" "integer xresolution" [64] "integer yresolution" [32]
WorldBegin
LightSource "point" "rgb I" [1 1 1]
Shape "sphere"
)")).document["camera"];
    EXPECT_EQ(camera["type"], "orthographic");
    EXPECT_NEAR(camera["view_height"].get<double>(), 4.0, 1e-5);
    EXPECT_FALSE(camera.contains("fov"));
    EXPECT_STREQ(importError("Camera \"orthographic\" \"float lensradius\" [0.1]\nWorldBegin\n").what(),
                 "bad.pbrt:1: Camera \"orthographic\": a lens (lensradius) is not supported");
}

// pbrt-v4 finds named materials once the whole file is read: scenes name one before the
// Include that makes it (pbrt-v4-scenes' contemporary-bathroom, its lights before
// materials.pbrt).
TEST(PbrtImport, AMaterialMayBeNamedBeforeItIsMade) {
    const ImportedScene s = import(R"(
AttributeBegin
  NamedMaterial "glass"
  Shape "sphere" "float radius" [0.3]
AttributeEnd
MakeNamedMaterial "both" "string type" "mix" "string materials" ["red" "later"] "float amount" 0.25
NamedMaterial "both"
Shape "sphere" "float radius" [0.2]
MakeNamedMaterial "glass" "string type" "dielectric" "float eta" 1.33
MakeNamedMaterial "red" "string type" "diffuse" "rgb reflectance" [0.8 0 0]
MakeNamedMaterial "later" "string type" "diffuse" "rgb reflectance" [0 0 0.8]
)");
    const Json& doc = s.document;
    const Json& shapes = doc["shapes"];
    ASSERT_EQ(shapes.size(), 4u);  // the light, the floor, the two spheres
    EXPECT_EQ(shapes[2]["material"], "glass");
    EXPECT_EQ(shapes[3]["material"], "both");
    EXPECT_EQ(doc["materials"]["glass"]["type"], "dielectric");
    EXPECT_FLOAT_EQ(doc["materials"]["glass"]["ior"].get<float>(), 1.33f);
    EXPECT_EQ(doc["materials"]["both"]["materials"], Json({"red", "later"}));
    EXPECT_FLOAT_EQ(doc["materials"]["later"]["albedo"][2].get<float>(), 0.8f);

    // Never made: refused where it was first named; lenient, pbrt-v4's default material.
    const std::string never = kHeader + "NamedMaterial \"nope\"\nShape \"sphere\"\nNamedMaterial \"nope\"\n";
    EXPECT_STREQ(importError(never).what(), "bad.pbrt:12: material \"nope\" is named here but never made (MakeNamedMaterial)");
    const ImportedScene lenient = importPbrt(writeScene("lenient.pbrt", never), true);
    EXPECT_EQ(lenient.document["materials"]["nope"], Json({{"type", "diffuse"}, {"albedo", {0.5, 0.5, 0.5}}}));
    ASSERT_EQ(lenient.warnings.size(), 1u);
    EXPECT_EQ(lenient.warnings[0], "lenient.pbrt:12: material \"nope\" is named here but never made (MakeNamedMaterial); "
                                   "rendered as pbrt-v4's default material, diffuse of reflectance 0.5 (lenient import)");
    // An interface made after shapes took it for a surface cannot be undone: refused.
    EXPECT_STREQ(importError(kHeader + "NamedMaterial \"gap\"\nShape \"sphere\"\n"
                                       "MakeNamedMaterial \"gap\" \"string type\" \"interface\"\n").what(),
                 "bad.pbrt:14: MakeNamedMaterial \"gap\": an interface (no surface), named at bad.pbrt:12 before it "
                 "is made here; make it before the shapes that use it");
}

TEST(PbrtImport, ErrorsNameFileAndLine) {
    const std::string head = "Camera \"perspective\"\nWorldBegin\n";
    EXPECT_STREQ(importError(head + "Material \"velvet\"\n").what(),
                 "bad.pbrt:3: material \"velvet\" is not supported (photon imports diffuse, coateddiffuse, dielectric, "
                 "thindielectric, conductor, coatedconductor, diffusetransmission, hair, measured, mix, interface, subsurface)");
    EXPECT_STREQ(importError(head + "MakeNamedMedium \"fire\" \"string type\" \"uniformgrid\" \"float density\" [1] "
                                    "\"float temperature\" [1500] \"rgb Le\" [1 1 1]\n").what(),
                 "bad.pbrt:3: medium \"fire\": give either \"Le\" or \"temperature\", not both");
    EXPECT_STREQ(importError(head + "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"float g\" [1]\n").what(),
                 "bad.pbrt:3: medium \"fog\": \"g\" must lie in (-1, 1)");
    EXPECT_STREQ(importError(head + "MakeNamedMedium \"smoke\" \"string type\" \"rgbgrid\"\n").what(),
                 "bad.pbrt:3: medium \"smoke\": a \"rgbgrid\" medium is not supported (photon renders \"homogeneous\", "
                 "\"uniformgrid\", \"nanovdb\" and \"cloud\" media)");
    EXPECT_STREQ(importError(head + "MakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
                                    "\"float density\" [1 2 3]\n").what(),
                 "bad.pbrt:3: medium \"smoke\": \"density\" holds 3 values, nx * ny * nz = 2");
    EXPECT_STREQ(importError(head + "MediumInterface \"tea\" \"\"\n").what(),
                 "bad.pbrt:3: MediumInterface: no medium named \"tea\"");
    EXPECT_STREQ(importError(head + "NamedMaterial \"nope\"\n").what(),
                 "bad.pbrt:3: material \"nope\" is named here but never made (MakeNamedMaterial)");
    EXPECT_STREQ(importError(head + "Shape \"sphere\" \"float zmin\" [2]\n").what(),
                 "bad.pbrt:3: sphere: zmin, zmax and phimax leave nothing of it");
    EXPECT_STREQ(importError(head + "Shape \"cylinder\" \"float zmin\" [1]\n").what(),
                 "bad.pbrt:3: cylinder: needs radius > 0 and zmin != zmax");
    EXPECT_STREQ(importError(head + "Shape \"nurbs\"\n").what(),
                 "bad.pbrt:3: Shape \"nurbs\" is not supported (photon imports trianglemesh, plymesh, sphere, disk, "
                 "cylinder, bilinearmesh, loopsubdiv, curve)");
    EXPECT_STREQ(importError(head + "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 5]\n").what(),
                 "bad.pbrt:3: Shape \"trianglemesh\": index 5 is out of range (3 vertices)");
    EXPECT_STREQ(importError("WorldBegin\nShape \"sphere\"\n").what(), "the pbrt scene has no Camera");
    EXPECT_STREQ(importError(head + "Shape \"sphere\" \"float radius\" [1 2]\n").what(),
                 "bad.pbrt:3: Shape \"sphere\": parameter \"radius\" needs 1 value, not 2");
    // The parser's own errors keep their location.
    EXPECT_EQ(importError(head + "Shape \"sphere\" \"float radius\" [1\n").path(), "bad.pbrt:3");
}

// A lenient import (photon-render --lenient) leaves out or replaces what photon cannot
// render, each with a warning naming the line and what was done, and keeps the rest: the
// same features refuse the strict import (ErrorsNameFileAndLine).
TEST(PbrtImport, LenientImportLeavesOutWhatPhotonCannotRender) {
    const std::string body = R"(
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [0 0 0] "rgb Le" [1 1 1]
MediumInterface "" "fog"
Attribute "shape" "float radius" [2]
Texture "noise" "spectrum" "ptex" "string filename" "noise.ptx"
MakeNamedMaterial "fur" "string type" "velvet" "string filename" "fur.bsdf"
MakeNamedMaterial "painted" "string type" "diffuse" "texture reflectance" "noise"
NamedMaterial "fur"
Shape "nurbs" "integer nu" [4]
Shape "sphere" "float radius" [0.5] "float zmax" [0.2]
LightSource "laser" "string filename" "slide.exr"
)";
    const ImportedScene s = importPbrt(writeScene("scene.pbrt", kHeader + body), true);
    const std::vector<std::string> expected = {
        "scene.pbrt:13: medium \"fog\" emits, but in proportion to its sigma_a (pbrt-v4's sigma_a Le), which is 0; "
        "its emission left out (lenient import)",
        "scene.pbrt:16: Texture \"noise\": class \"ptex\" is not supported (photon imports imagemap, checkerboard, bilerp, "
        "dots, fbm, wrinkled, windy, marble, scale, mix, directionmix, constant); the constant 0.5 used (lenient import)",
        "scene.pbrt:17: material \"velvet\" is not supported (photon imports diffuse, coateddiffuse, dielectric, "
        "thindielectric, conductor, coatedconductor, diffusetransmission, hair, measured, mix, interface, subsurface); rendered as a grey "
        "diffuse material (lenient import)",
        "scene.pbrt:20: Shape \"nurbs\" is not supported (photon imports trianglemesh, plymesh, sphere, disk, cylinder, "
        "bilinearmesh, loopsubdiv, curve); left out (lenient import)",
        "scene.pbrt:22: LightSource \"laser\" is not supported (photon imports point, spot, goniometric, projection, "
        "distant, infinite); left out (lenient import)"};
    EXPECT_EQ(s.warnings, expected);
    const Json& m = s.document["materials"];
    EXPECT_EQ(m["fur"], Json::parse(R"({"type": "diffuse", "albedo": [0.5, 0.5, 0.5]})"));
    EXPECT_EQ(m["painted"]["albedo"], Json::parse("[0.5, 0.5, 0.5]"));
    // The header's quad light and floor, and the part of a sphere (a mesh); no nurbs.
    ASSERT_EQ(s.document["shapes"].size(), 3u);
    EXPECT_EQ(s.document["shapes"][2]["type"], "mesh");
    EXPECT_EQ(s.document["shapes"][2]["material"], "fur");
    EXPECT_EQ(s.document["shapes"][2]["medium"], Json::parse(R"({"outside": "fog"})"));
    EXPECT_EQ(s.document["media"], Json::parse(R"({"fog": {"absorption": [0, 0, 0], "scattering": [1, 1, 1]}})"));
    EXPECT_FALSE(s.document.contains("lights"));
    loadImportedScene(s, scratch());  // what the lenient import wrote loads
    // Strict, the first of them is refused.
    EXPECT_THROW(importPbrt(writeScene("scene.pbrt", kHeader + body)), SceneError);
}

TEST(PbrtImport, WhatIsLeftOutIsWarned) {
    const ImportedScene s = import(R"(
Shape "trianglemesh" "point3 P" [0 0 0 1 0 0 0 1 0] "vector3 S" [1 0 0 1 0 0 1 0 0]
)");
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_EQ(s.warnings.back(), "scene.pbrt:13: Shape \"trianglemesh\": parameter \"S\" (vector3) ignored");
}

// photon-convert's JSON (meshes as PLY files beside it) renders the image the .pbrt does,
// bit for bit: import and conversion make one scene.
TEST(PbrtImport, ConvertedJsonRendersTheSameImage) {
    const fs::path pbrt = writeScene("convert/scene.pbrt", kHeader + R"(
Material "coateddiffuse" "rgb reflectance" [0.7 0.3 0.2] "float roughness" [0.05]
Shape "sphere" "float radius" [0.4]
Shape "disk" "float radius" [0.3] "float height" [1.2]
)");
    const fs::path json = scratch() / "converted" / "scene.json";
    ConversionReport report = convertScene(pbrt, json);
    EXPECT_EQ(report.written.size(), 3u);  // the light's quad, the floor, the disk
    const std::vector<SettingOverride> settings = {{"render.passes", "3"}, {"render.photons_per_pass", "20000"}};
    Image fromPbrt = test::renderImage(SceneFile::read(pbrt, settings).description());
    Image fromJson = test::renderImage(SceneFile::read(json, settings).description());
    ASSERT_EQ(fromPbrt.rgb.size(), fromJson.rgb.size());
    for (size_t i = 0; i < fromPbrt.rgb.size(); ++i) ASSERT_EQ(fromPbrt.rgb[i], fromJson.rgb[i]) << i;
    EXPECT_GT(luminance(test::meanOver(fromPbrt, 0, 0, fromPbrt.width, fromPbrt.height)), 0.01f);
}

}  // namespace
}  // namespace photon

