// Density grids from NanoVDB files (pbrt-v4's "nanovdb" medium): a grid written here with
// NanoVDB's own builder, uncompressed and with each codec pbrt-v4's files may use, read back
// through the scene file and placed in the world by the grid's voxel size and origin and the
// medium's transform. (Compiled outside the unity batch: the codec switches below must not
// reach other sources.)
#define NANOVDB_USE_ZIP
#define NANOVDB_USE_BLOSC
#include <gtest/gtest.h>
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>
#include "math/rng.h"
#include "math/spectrum_rgb.h"
#include "scene_loader_fixture.h"
#include "support/pbrt_import_fixture.h"

namespace photon::nanovdb_density_tests {
namespace {

using test::expectError;
using test::load;

// A linear density 1 + i + 2 j + k / 2 at index (i, j, k) for i in [2, 5], j in [-1, 1],
// k in [0, 3], of voxels 0.5 wide with index (0, 0, 0) at (1, 0, 0).
double linearDensity(double i, double j, double k) { return 1 + i + 2 * j + 0.5 * k; }

void writeCloud(const std::filesystem::path& file, nanovdb::io::Codec codec) {
    nanovdb::GridBuilder<float> builder(0.0f);
    auto acc = builder.getAccessor();
    for (int i = 2; i <= 5; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = 0; k <= 3; ++k) acc.setValue(nanovdb::Coord(i, j, k), float(linearDensity(i, j, k)));
    std::filesystem::create_directories(file.parent_path());
    nanovdb::io::writeGrid(file.string(), builder.getHandle<>(0.5, nanovdb::Vec3d(1, 0, 0), "density"), codec);
}

Json cloudScene(const std::string& file) {
    Json doc = test::fullScene();
    doc["media"] = {{"cloud",
                     {{"scattering", {1, 1, 1}},
                      {"density", {{"file", file}, {"transform", {{"translate", {0, 0, 10}}}}}}}}};
    return doc;
}

TEST(NanoVdbDensity, AFilesGridIsSampledWhereItsVoxelsAre) {
    const std::pair<nanovdb::io::Codec, const char*> codecs[] = {
        {nanovdb::io::Codec::NONE, "none"}, {nanovdb::io::Codec::ZIP, "zip"}, {nanovdb::io::Codec::BLOSC, "blosc"}};
    for (const auto& [codec, name] : codecs) {
        SCOPED_TRACE(name);
        const std::string file = std::string("volumes/cloud-") + name + ".nvdb";
        writeCloud(test::fixture().scene / file, codec);
        const SceneDescription d = load(cloudScene(file));
        ASSERT_TRUE(d.media[0].density);
        const DensityGrid& grid = *d.media[0].density;
        auto world = [](double i, double j, double k) {
            return Vec3(float(1 + 0.5 * i), float(0.5 * j), float(0.5 * k + 10));
        };
        // Trilinear between the voxels reproduces a linear density.
        EXPECT_NEAR(grid.at(world(3.5, 0.25, 1.25)), linearDensity(3.5, 0.25, 1.25), 1e-4);
        EXPECT_NEAR(grid.at(world(2, -1, 0)), linearDensity(2, -1, 0), 1e-4);
        // Half a voxel past the last one, toward the background's 0; outside, nothing.
        EXPECT_NEAR(grid.at(world(5.5, 0, 1)), 0.5 * linearDensity(5, 0, 1), 1e-4);
        EXPECT_EQ(grid.at(world(5.75, 0, 1)), 0.0f);
        EXPECT_EQ(grid.at(world(3, 0, -1)), 0.0f);
        // Along x through j = 0, k = 1 (world y 0, z 10.5), from index 2 to 5: the linear
        // density's integral times the voxel's 0.5.
        const double inside = 0.5 * (3 * linearDensity(3.5, 0, 1));
        EXPECT_NEAR(grid.integral(world(2, 0, 1), {1, 0, 0}, 1.5f), inside, 1e-4);
        EXPECT_FLOAT_EQ(grid.maxValue(), float(linearDensity(5, 1, 3)));
    }
}

// The sparse grid and the same samples given as values in a box of the voxels' extent are
// one density: equal integrals along rays that cross it every way.
TEST(NanoVdbDensity, ASparseGridIsTheDenseGridOfItsSamples) {
    writeCloud(test::fixture().scene / "volumes/cloud.nvdb", nanovdb::io::Codec::NONE);
    Json doc = cloudScene("volumes/cloud.nvdb");
    Json values = Json::array();
    for (int k = 0; k <= 3; ++k)
        for (int j = -1; j <= 1; ++j)
            for (int i = 2; i <= 5; ++i) values.push_back(linearDensity(i, j, k));
    doc["media"]["box"] = {{"scattering", {1, 1, 1}},
                           {"density",
                            {{"resolution", {4, 3, 4}},
                             {"values", values},
                             {"bounds", {{1.75, -0.75, -0.25}, {3.75, 0.75, 1.75}}},
                             {"transform", {{"translate", {0, 0, 10}}}}}}};
    const SceneDescription d = load(doc);
    const DensityGrid &sparse = *d.media[0].density, &dense = *d.media[1].density;
    Rng rng(2, 0, 3, StreamPurpose::Camera);
    for (int ray = 0; ray < 50; ++ray) {
        const Vec3 o{2.75f + 3 * (rng.uniform() - 0.5f), 3 * (rng.uniform() - 0.5f), 10.75f + 3 * (rng.uniform() - 0.5f)};
        const Vec3 dir = normalize(Vec3{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f});
        EXPECT_NEAR(sparse.integral(o, dir, 6.0f), dense.integral(o, dir, 6.0f), 1e-4) << ray;
    }
}

// pbrt-v4's nanovdb medium emits by its file's "temperature" grid, times "Lescale": a file
// holding a density of 1 and a temperature of 1,700 K over the same voxels, imported with
// "temperaturecutoff" 200 and "temperaturescale" 2, glows with pbrt-v4's blackbody at
// 3,000 K times 3 where the voxels are, and a file without one does not.
TEST(NanoVdbDensity, ATemperatureGridMakesAPbrtMediumEmit) {
    auto constantGrid = [](float value, const char* name) {
        nanovdb::GridBuilder<float> builder(0.0f);
        auto acc = builder.getAccessor();
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < 4; ++k) acc.setValue(nanovdb::Coord(i, j, k), value);
        return builder.getHandle<>(0.25, nanovdb::Vec3d(0, 0, 0), name);
    };
    // Beside the pbrt file, and beside the JSON scene its media are loaded in.
    for (const std::filesystem::path& dir :
         {test::pbrt_import::scratch() / "volumes", test::fixture().scene / "volumes"}) {
        std::filesystem::create_directories(dir);
        std::vector<nanovdb::GridHandle<>> grids;
        grids.push_back(constantGrid(1.0f, "density"));
        grids.push_back(constantGrid(1700.0f, "temperature"));
        nanovdb::io::writeGrids((dir / "fire.nvdb").string(), grids);
        nanovdb::io::writeGrid((dir / "smoke.nvdb").string(), constantGrid(1.0f, "density"));
    }
    const std::string medium = "MakeNamedMedium \"m\" \"string type\" \"nanovdb\" \"rgb sigma_a\" [1 1 1] "
                               "\"float Lescale\" 3 \"float temperaturecutoff\" 200 \"float temperaturescale\" 2 "
                               "\"string filename\" ";
    const ImportedScene fire = test::pbrt_import::import(medium + "\"volumes/fire.nvdb\"\n");
    const Json& emission = fire.document["media"]["m"]["emission"];
    EXPECT_EQ(emission, Json::parse(R"({"scale": 3, "temperature": {"file": "volumes/fire.nvdb", "grid": "temperature"},
                                         "temperature_offset": 200, "temperature_scale": 2})"));
    Json doc = test::fullScene();
    doc["media"] = fire.document["media"];
    const SceneDescription d = load(doc);
    ASSERT_TRUE(d.media[0].emits());
    const Color expected = 3.0f * blackbodyPeakColor(3000);
    const Color seen = d.media[0].emission->at({0.25f, 0.5f, 0.5f});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], expected[c], 1e-4f * expected[c]) << c;
    EXPECT_EQ(d.media[0].emission->at({-1, -1, -1}), Color(0.0f));  // no voxels there: 0 K
    const ImportedScene smoke = test::pbrt_import::import(medium + "\"volumes/smoke.nvdb\"\n");
    EXPECT_FALSE(smoke.document["media"]["m"].contains("emission"));
}

TEST(NanoVdbDensity, ErrorsNameTheFile) {
    writeCloud(test::fixture().scene / "volumes/cloud.nvdb", nanovdb::io::Codec::NONE);
    test::writeText(test::fixture().scene / "volumes/broken.nvdb", "not a NanoVDB file");
    expectError([](Json& doc) { doc = cloudScene("volumes/missing.nvdb"); }, "media.cloud.density.file",
                "file not found: volumes/missing.nvdb");
    expectError(
        [](Json& doc) {
            doc = cloudScene("volumes/cloud.nvdb");
            doc["media"]["cloud"]["density"]["grid"] = "temperature";
        },
        "media.cloud.density.file", "holds no grid named \"temperature\"");
    expectError(
        [](Json& doc) {
            doc = cloudScene("volumes/cloud.nvdb");
            doc["media"]["cloud"]["density"]["values"] = {1};
        },
        "media.cloud.density", "give either \"file\" or \"resolution\" and \"values\", not both");
    const SceneError broken = test::errorFromText(cloudScene("volumes/broken.nvdb").dump());
    EXPECT_EQ(broken.path(), "media.cloud.density.file");
    EXPECT_NE(std::string(broken.what()).find("cannot read it as NanoVDB"), std::string::npos) << broken.what();
    // A file cut short is refused, not followed into memory it does not hold.
    std::ifstream whole(test::fixture().scene / "volumes/cloud.nvdb", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
    test::writeText(test::fixture().scene / "volumes/cut.nvdb", bytes.substr(0, bytes.size() * 2 / 3));
    const SceneError cut = test::errorFromText(cloudScene("volumes/cut.nvdb").dump());
    EXPECT_EQ(cut.path(), "media.cloud.density.file") << cut.what();
}

// pbrt-v4's "nanovdb" medium names its file; the current transform places the grid.
TEST(NanoVdbDensity, APbrtNanoVdbMediumNamesItsFile) {
    using namespace test::pbrt_import;
    const ImportedScene s = import("AttributeBegin\nTranslate 0 1 0\nMakeNamedMedium \"cloud\" \"string type\" \"nanovdb\" "
                                   "\"string filename\" \"volumes/cloud.nvdb\" \"spectrum sigma_s\" [300 2 830 2] "
                                   "\"spectrum sigma_a\" [300 0 830 0]\nAttributeEnd\n");
    const Json& m = s.document["media"]["cloud"];
    EXPECT_EQ(m["density"]["file"], "volumes/cloud.nvdb");
    EXPECT_EQ(m["density"]["grid"], "density");
    EXPECT_EQ(m["density"]["transform"]["matrix"], Json({1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1}));
    EXPECT_NEAR(vec(m["scattering"]).x, 2.0f, 1e-5f);
    EXPECT_STREQ(importError(kHeader + "MakeNamedMedium \"cloud\" \"string type\" \"nanovdb\"\n").what(),
                 "bad.pbrt:12: medium \"cloud\": a \"nanovdb\" medium needs a \"filename\"");
}

}  // namespace
}  // namespace photon::nanovdb_density_tests
