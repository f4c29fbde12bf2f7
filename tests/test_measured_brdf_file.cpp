// Measured-BRDF files: the tensor format's reader (scene/tensor_file.h) against damaged and
// hostile files, the BRDF's fields and shapes (scene/measured_brdf_file.h), and the
// material as the JSON scene and the pbrt importer name it.
#include <gtest/gtest.h>
#include <cstring>
#include <stdexcept>
#include <string>
#include "description/scene_description.h"
#include "import/pbrt/pbrt_import.h"
#include "materials/measured_brdf.h"
#include "scene/measured_brdf_file.h"
#include "scene/scene_loader.h"
#include "scene/tensor_file.h"
#include "measured_brdf_tables.h"
#include "pbrt_import_fixture.h"
#include "scene_loader_fixture.h"

namespace photon::measured_brdf_file_tests {
namespace {

using test::GgxTableOptions;

// What reading `bytes` as "x.bsdf" throws; a test failure if it reads.
std::string tensorError(const std::string& bytes) {
    try {
        TensorFile file(bytes, "x.bsdf");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "read without error";
    return "";
}

std::string brdfError(const std::vector<TensorFieldData>& fields) {
    try {
        readMeasuredBrdf(TensorFile(tensorFileBytes(fields), "x.bsdf"));
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "read without error";
    return "";
}

GgxTableOptions smallTable() {
    GgxTableOptions o;
    o.n = 8;
    o.thetas = 3;
    return o;
}

TEST(TensorFile, FieldsReadBackAsWritten) {
    const TensorFile file(test::ggxTableFile(smallTable()), "x.bsdf");
    const auto& vndf = file.field("vndf", TensorFile::Type::Float32, 4);
    EXPECT_EQ(vndf.shape, (std::vector<uint64_t>{1, 3, 8, 8}));
    const std::vector<float> thetas = file.floats("theta_i", 1);
    ASSERT_EQ(thetas.size(), 3u);
    EXPECT_FLOAT_EQ(thetas[0], 0.0f);
    EXPECT_FLOAT_EQ(thetas[2], float(0.5 * kPi * 85.0 / 90.0));
    EXPECT_EQ(file.field("description", TensorFile::Type::UInt8, 1).bytes, "ggx ");
}

TEST(TensorFile, DamagedFilesAreRefusedWithWhatIsWrong) {
    const std::string good = test::ggxTableFile(smallTable());
    EXPECT_EQ(tensorError("tensor_file"), "x.bsdf: not a tensor file (no \"tensor_file\" signature)");
    EXPECT_EQ(tensorError("PK" + good.substr(2)), "x.bsdf: not a tensor file (no \"tensor_file\" signature)");
    std::string version = good;
    version[12] = 2;
    EXPECT_EQ(tensorError(version), "x.bsdf: version 2.0 (expected 1.0)");
    EXPECT_EQ(tensorError(good.substr(0, 40)), "x.bsdf: the header ends inside a field's shape");
    // A file cut inside its data: the last field's data lie past its end.
    EXPECT_EQ(tensorError(good.substr(0, good.size() - 4)),
              "x.bsdf: field \"spectra\" lies past the end of the file (" + std::to_string(good.size() - 4) + " bytes)");
    // Counts a damaged or hostile header may hold: nothing is allocated for them.
    std::string manyFields = good;
    const uint32_t count = 1u << 31;
    std::memcpy(manyFields.data() + 14, &count, 4);
    EXPECT_EQ(tensorError(manyFields), "x.bsdf: 2147483648 fields (at most 4096)");
    TensorFieldData huge{"huge", TensorFile::Type::Float64, {1ull << 40, 1ull << 40}, ""};
    EXPECT_EQ(tensorError(tensorFileBytes({huge})), "x.bsdf: field \"huge\" is larger than the file");
    TensorFieldData odd{"odd", TensorFile::Type(12), {1}, "x"};
    EXPECT_EQ(tensorError(tensorFileBytes({odd})), "x.bsdf: field \"odd\" has an unknown element type 12");
    TensorFieldData twice{"a", TensorFile::Type::UInt8, {1}, "x"};
    EXPECT_EQ(tensorError(tensorFileBytes({twice, twice})), "x.bsdf: field \"a\" is given twice");
}

TEST(MeasuredBrdfFile, FieldsOfTheWrongShapeAreRefused) {
    auto without = [](const std::string& name) {
        auto fields = test::ggxTableFields(smallTable());
        std::erase_if(fields, [&](const TensorFieldData& f) { return f.name == name; });
        return fields;
    };
    auto replaced = [](TensorFieldData field) {
        auto fields = test::ggxTableFields(smallTable());
        for (auto& f : fields)
            if (f.name == field.name) f = field;
        return fields;
    };
    EXPECT_EQ(brdfError(without("ndf")), "x.bsdf: has no field \"ndf\"");
    EXPECT_EQ(brdfError(without("wavelengths")), "x.bsdf: has no field \"wavelengths\"");
    EXPECT_EQ(brdfError(replaced(test::floatField("luminance", {1, 3, 4, 4}, std::vector<float>(48, 1.0f)))),
              "x.bsdf: field \"luminance\" has shape [1, 3, 4, 4], expected 1 x 3 x 8 x 8 (phi_i x theta_i x n x n)");
    EXPECT_EQ(brdfError(replaced(test::floatField("theta_i", {3}, {0.0f, 0.5f, 0.2f}))),
              "x.bsdf: fields \"phi_i\" and \"theta_i\" must be ascending");
    EXPECT_EQ(brdfError(replaced(test::floatField("luminance", {1, 3, 8, 8}, std::vector<float>(192, -1.0f)))),
              "x.bsdf: fields \"vndf\" and \"luminance\" are densities and must not be negative");
    EXPECT_EQ(brdfError(replaced({"ndf", TensorFile::Type::Float64, {8, 8}, std::string(512, '\0')})),
              "x.bsdf: field \"ndf\" must have 2 dimension(s) of 32-bit floats");
    EXPECT_EQ(brdfError(replaced(test::floatField("phi_i", {3}, {-1.0f, 0.0f, 1.0f}))),
              "x.bsdf: an anisotropic table's \"phi_i\" must span the circle (from -pi to pi)");
}

// {"type": "measured", "file": ...} in a JSON scene: the file's BRDF, read once for the two
// materials that name it; a damaged file is refused at the material's "file".
TEST(MeasuredBrdfFile, TheJsonSceneNamesItsFile) {
    test::writeText(test::fixture().scene / "brdfs/ggx.bsdf", test::ggxTableFile(smallTable()));
    test::writeText(test::fixture().scene / "brdfs/cut.bsdf", test::ggxTableFile(smallTable()).substr(0, 100));
    Json doc = test::fullScene();
    doc["materials"]["a"] = {{"type", "measured"}, {"file", "brdfs/ggx.bsdf"}};
    doc["materials"]["b"] = {{"type", "measured"}, {"file", "brdfs/ggx.bsdf"}};
    const SceneDescription d = test::load(doc);
    const Material& a = *d.materials[d.materials.size() - 2];
    const Material& b = *d.materials.back();
    EXPECT_EQ(a.lobes(), unsigned(kGlossyLobe));
    const MaterialPtr direct = makeMeasured(readMeasuredBrdf(TensorFile(test::ggxTableFile(smallTable()), "ggx")));
    const Vec3 wo = normalize(Vec3(0.3f, 0.1f, 0.9f)), wi = normalize(Vec3(-0.2f, 0.3f, 0.8f));
    const Color fa = a.eval(wo, wi, {}, TransportMode::Radiance), fb = b.eval(wo, wi, {}, TransportMode::Radiance);
    const Color expected = direct->eval(wo, wi, {}, TransportMode::Radiance);
    EXPECT_GT(expected.y, 0.0f);
    EXPECT_EQ(fa.y, expected.y);
    EXPECT_EQ(fb.y, expected.y);
    test::expectError([](Json& doc) { doc["materials"]["a"] = {{"type", "measured"}, {"file", "brdfs/cut.bsdf"}}; },
                      "materials.a.file", "brdfs/cut.bsdf: field \"theta_i\" lies past the end of the file (100 bytes)");
    test::expectError([](Json& doc) { doc["materials"]["a"] = {{"type", "measured"}}; }, "materials.a.file",
                      "missing required field");
}

// pbrt-v4's Material "measured" with its "filename" becomes photon's measured material.
TEST(MeasuredBrdfFile, ThePbrtImporterReadsMeasuredMaterials) {
    using namespace test::pbrt_import;
    test::writeText(scratch() / "bsdfs/ggx.bsdf", test::ggxTableFile(smallTable()));
    const ImportedScene s = import("Material \"measured\" \"string filename\" \"bsdfs/ggx.bsdf\"\n"
                                   "Shape \"sphere\" \"float radius\" 0.5\n");
    bool found = false;
    for (const auto& [name, m] : s.document["materials"].items())
        if (m["type"] == "measured") {
            EXPECT_EQ(m, Json({{"type", "measured"}, {"file", "bsdfs/ggx.bsdf"}}));
            found = true;
        }
    EXPECT_TRUE(found) << s.document["materials"].dump();
    const SceneDescription d = loadImportedScene(s, scratch());
    EXPECT_TRUE(std::any_of(d.materials.begin(), d.materials.end(),
                            [](const MaterialPtr& m) { return m->lobes() == unsigned(kGlossyLobe); }));
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nMaterial \"measured\"\n").what(),
                 "bad.pbrt:3: measured: needs a \"string filename\" (a .bsdf file)");
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nMaterial \"measured\" \"string filename\" \"../x.bsdf\"\n").what(),
                 "bad.pbrt:3: measured: \"../x.bsdf\": must be a relative path inside the scene folder");
}

}  // namespace
}  // namespace photon::measured_brdf_file_tests
