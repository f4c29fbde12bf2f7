// pbrt-v4's media imported onto photon's (docs/import.md): the subsurface material's medium
// and the media whose density varies in space ("uniformgrid" here, "nanovdb" in
// test_nanovdb_density.cpp).
#include <gtest/gtest.h>
#include "import/pbrt/scattering_presets.h"
#include "pbrt_import_fixture.h"

namespace photon::pbrt_import_media_tests {
namespace {

using namespace test::pbrt_import;

// A medium's absorption and scattering (their green channel), within 1e-5 relative.
void expectCoefficients(const Json& medium, float absorption, float scattering) {
    EXPECT_NEAR(vec(medium["absorption"]).y, absorption, 1e-5f * absorption);
    EXPECT_NEAR(vec(medium["scattering"]).y, scattering, 1e-5f * scattering);
}

// pbrt-v4's "subsurface" becomes a dielectric whose shapes hold a scattering medium, its
// coefficients as pbrt-v4's SubsurfaceMaterial::Create finds them, times "scale".
TEST(PbrtImport, SubsurfaceIsADielectricAroundAScatteringMedium) {
    const ImportedScene s = import(R"(
AttributeBegin
  Material "subsurface" "string name" "Skin1" "float scale" 10 "float eta" 1.4 "float roughness" 0.2
  Shape "sphere" "float radius" 0.3
AttributeEnd
Material "subsurface" "rgb reflectance" [0.5 0.2 0.8] "rgb mfp" [0.1 0.2 0.4] "float scale" 0.5
Shape "sphere" "float radius" 0.2
Material "subsurface"
Shape "sphere" "float radius" 0.1
)");
    const Json& doc = s.document;
    const Json &skin = doc["shapes"][2], &reflecting = doc["shapes"][3], &milk = doc["shapes"][4];
    const Json& material = doc["materials"][skin["material"].get<std::string>()];
    EXPECT_EQ(material["type"], "dielectric");
    EXPECT_FLOAT_EQ(material["ior"].get<float>(), 1.4f);
    // As a dielectric's: pbrt's remapped alpha = sqrt(0.2), photon's roughness sqrt(alpha).
    EXPECT_NEAR(material["roughness"].get<double>(), std::pow(0.2, 0.25), 1e-6);
    EXPECT_FALSE(material.contains(std::string("\x01medium")));
    // Jensen et al. 2001's skin 1 (mm^-1) times 10, with g = 0.
    const Json& skinMedium = doc["media"][skin["medium"]["inside"].get<std::string>()];
    const Color sigmaA = vec(skinMedium["absorption"]), sigmaS = vec(skinMedium["scattering"]);
    EXPECT_NEAR(sigmaA.x, 0.32, 1e-5);
    EXPECT_NEAR(sigmaA.z, 4.8, 1e-5);
    EXPECT_NEAR(sigmaS.y, 8.8, 1e-5);
    EXPECT_FALSE(skinMedium.contains("g"));
    // From a reflectance and a mean free path (times scale): a medium given by its look,
    // whose coefficients photon's loader finds (media/diffusion_dipole.h).
    const Json& fromReflectance = doc["media"][reflecting["medium"]["inside"].get<std::string>()];
    EXPECT_EQ(fromReflectance["reflectance"], Json({0.5f, 0.2f, 0.8f}));
    EXPECT_EQ(fromReflectance["mean_free_path"], Json({0.05f, 0.1f, 0.2f}));
    EXPECT_FLOAT_EQ(fromReflectance["boundary_ior"].get<float>(), 1.33f);
    EXPECT_FALSE(fromReflectance.contains("absorption"));
    // Every subsurface medium's walk counts as one vertex, as pbrt-v4's BSSRDF does.
    EXPECT_EQ(fromReflectance["subsurface"], true);
    EXPECT_EQ(skinMedium["subsurface"], true);
    // Nothing given: pbrt-v4's whole milk.
    const Json& milkMedium = doc["media"][milk["medium"]["inside"].get<std::string>()];
    EXPECT_NEAR(vec(milkMedium["scattering"]).z, 3.77, 1e-5);
    EXPECT_FLOAT_EQ(doc["materials"][milk["material"].get<std::string>()]["ior"].get<float>(), 1.33f);

    // A homogeneous medium's "preset" reads the same table, times its "scale".
    const ImportedScene cream = import("MakeNamedMedium \"c\" \"string type\" \"homogeneous\" \"string preset\" \"Cream\" "
                                       "\"float scale\" 100 \"float g\" 0.3\n");
    EXPECT_NEAR(vec(cream.document["media"]["c"]["scattering"]).x, 738, 1e-3);
    EXPECT_NEAR(vec(cream.document["media"]["c"]["absorption"]).z, 1.63, 1e-5);
    EXPECT_NEAR(cream.document["media"]["c"]["g"].get<double>(), 0.3, 1e-6);

    EXPECT_STREQ(importError(kHeader + "Material \"subsurface\" \"string name\" \"Jam\"\n").what(),
                 "bad.pbrt:12: subsurface: no measured material named \"Jam\" (photon has Apple, Chicken1, Chicken2, "
                 "Cream, Ketchup, Marble, Potato, Skimmilk, Skin1, Skin2, Spectralon, Wholemilk)");
    // A textured reflectance is the medium's texture; a textured mean free path is refused.
    test::writeImage<uint8_t>(scratch() / "albedo.png", 2, 1, 3, {200, 150, 120, 180, 120, 100});
    const ImportedScene head = import("Texture \"albedo\" \"spectrum\" \"imagemap\" \"string filename\" \"albedo.png\"\n"
                                      "Material \"subsurface\" \"texture reflectance\" \"albedo\" \"rgb mfp\" [0.0013 0.00095 0.00067]\n"
                                      "Shape \"sphere\" \"float radius\" 0.1\n");
    const Json& skinOfHead = head.document["media"][head.document["shapes"][2]["medium"]["inside"].get<std::string>()];
    EXPECT_EQ(skinOfHead["reflectance"]["type"], Json("image"));
    EXPECT_EQ(skinOfHead["mean_free_path"], Json({0.0013f, 0.00095f, 0.00067f}));
    EXPECT_STREQ(importError(kHeader + "Texture \"t\" \"spectrum\" \"constant\" \"rgb value\" [0.5 0.5 0.5]\n"
                                       "Material \"subsurface\" \"rgb reflectance\" [0.5 0.5 0.5] \"texture mfp\" \"t\"\n").what(),
                 "bad.pbrt:13: subsurface: a textured \"mfp\" is not supported (only \"reflectance\" may be a texture)");
}

// pbrt-v4's "uniformgrid" medium, made as smoke-plume makes it: the density in a file of its
// own whose MakeNamedMedium the main file's coefficients finish after the Include, under a
// transform that places the medium's box.
TEST(PbrtImport, AUniformGridMediumKeepsItsDensityItsBoxAndItsPlace) {
    writeScene("geometry/density.pbrt",
               "MakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"integer ny\" 1 "
               "\"integer nz\" 3\n  \"float density\" [0 1 2 3 4 5] \"point3 p0\" [-1 -1 -1] \"point3 p1\" [1 1 1]\n");
    const ImportedScene s = import("AttributeBegin\nTranslate 1 2 3\nScale 2 2 2\nInclude \"geometry/density.pbrt\"\n"
                                   "  \"spectrum sigma_a\" [300 1 830 1] \"spectrum sigma_s\" [300 4 830 4] \"float scale\" 0.5\n"
                                   "MediumInterface \"smoke\" \"\"\nMaterial \"interface\"\nShape \"sphere\" \"float radius\" 1\n"
                                   "AttributeEnd\n");
    const Json& m = s.document["media"]["smoke"];
    expectCoefficients(m, 0.5f, 2.0f);
    const Json& grid = m["density"];
    EXPECT_EQ(grid["resolution"], Json({2, 1, 3}));
    EXPECT_EQ(grid["values"], Json({0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(grid["bounds"], Json({{-1, -1, -1}, {1, 1, 1}}));
    EXPECT_EQ(grid["transform"]["matrix"], Json({2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3, 0, 0, 0, 1}));
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

// pbrt-v4's procedural "cloud", made as pbrt-v4-scenes' clouds.pbrt makes it: its coefficients
// as given (no "scale"), its noise's parameters and its box, for the loader to sample.
TEST(PbrtImport, ACloudMediumKeepsItsNoiseAndItsBox) {
    const ImportedScene s = import(
        "MakeNamedMedium \"c\" \"string type\" \"cloud\" \"spectrum sigma_s\" [200 10 900 10] "
        "\"spectrum sigma_a\" [200 .01 900 .01] \"float density\" 2 \"float frequency\" 4 \"point3 p1\" [1 2 1]\n"
        "MediumInterface \"c\" \"\"\nMaterial \"\"\nTranslate .5 .5 .5\nShape \"sphere\" \"float radius\" 1\n");
    const Json& m = s.document["media"]["c"];
    expectCoefficients(m, 0.01f, 10.0f);
    EXPECT_EQ(m["density"], Json({{"cloud", {{"density", 2}, {"frequency", 4}}}, {"bounds", {{0, 0, 0}, {1, 2, 1}}}}));
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nMakeNamedMedium \"c\" \"string type\" \"cloud\" "
                             "\"float frequency\" 0\n").what(),
                 "bad.pbrt:3: medium \"c\": \"frequency\" must be finite and > 0");
}

// Media that emit, as pbrt-v4's media read their light: a homogeneous medium's "Le" times
// "Lescale"; a uniform grid's "Le" (scaled to unit luminance unless "rgb") over pbrt-v4's
// single "Lescale" sample where no grid of them is given, or a temperature grid with its
// offset and scale; and a medium that would emit but absorbs nothing, refused.
TEST(PbrtImport, MediaThatEmitKeepTheirLight) {
    const ImportedScene s = import(
        "MakeNamedMedium \"glow\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [2 2 2] \"rgb sigma_s\" [0 0 0] "
        "\"rgb Le\" [1 2 3] \"float Lescale\" 4\n"
        "MakeNamedMedium \"gas\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"float density\" [1 2] "
        "\"spectrum Le\" [400 1 700 1] \"point3 p1\" [2 1 1]\n"
        "MakeNamedMedium \"fire\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"float density\" [1 2] "
        "\"float temperature\" [900 1400] \"float Lescale\" [0.5 3] \"float temperaturecutoff\" 200 "
        "\"float temperaturescale\" 2\n");
    const Json& media = s.document["media"];
    EXPECT_EQ(media["glow"]["emission"], Json::parse(R"({"radiance": [1, 2, 3], "scale": 4})"));
    const Json& gas = media["gas"]["emission"];
    EXPECT_NEAR(luminance(vec(gas["radiance"])), 1.0f, 1e-4f);  // a spectrum, at unit luminance
    EXPECT_EQ(gas["grid"], Json::parse(R"({"resolution": [1, 1, 1], "values": [1], "bounds": [[0, 0, 0], [2, 1, 1]]})"));
    EXPECT_EQ(media["fire"]["emission"], Json::parse(R"({
        "grid": {"resolution": [2, 1, 1], "values": [0.5, 3], "bounds": [[0, 0, 0], [1, 1, 1]]},
        "temperature": {"resolution": [2, 1, 1], "values": [900, 1400], "bounds": [[0, 0, 0], [1, 1, 1]]},
        "temperature_offset": 200, "temperature_scale": 2})"));
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nMakeNamedMedium \"f\" \"string type\" \"homogeneous\" "
                             "\"rgb sigma_a\" [0 0 0] \"rgb Le\" [1 1 1]\n").what(),
                 "bad.pbrt:3: medium \"f\" emits, but in proportion to its sigma_a (pbrt-v4's sigma_a Le), which is 0");
}

}  // namespace
}  // namespace photon::pbrt_import_media_tests
