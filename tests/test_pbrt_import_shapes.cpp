// The pbrt-v4 importer's shapes and what bounds them: spheres, disks, partial quadrics as
// meshes, instances and PLY files, Attribute defaults, and absorbing media.
#include <gtest/gtest.h>
#include <cmath>
#include <photon/errors.h>
#include "description/scene_description.h"
#include "import/pbrt/pbrt_import.h"
#include "pbrt_import_fixture.h"
#include "scene/ply_mesh.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace photon {
namespace {

using namespace test::pbrt_import;

// Media that absorb (pbrt-v4's homogeneous medium with sigma_s 0): under "media", sigma_a
// times scale; shapes under a MediumInterface that differs on its two sides bound them
// (inside, then outside); an "interface" material there becomes a dielectric of index 1
// (a boundary with no surface), and is left out where it bounds nothing.
TEST(PbrtImport, AbsorbingMediaAndTheShapesThatBoundThem) {
    const ImportedScene s = import(R"(
MakeNamedMedium "tea" "string type" "homogeneous" "rgb sigma_a" [0.1 0.3 0.7] "rgb sigma_s" [0 0 0] "float scale" [2]
MakeNamedMaterial "water" "string type" "dielectric" "float eta" [1.33]
MakeNamedMaterial "boundary" "string type" "interface"
AttributeBegin
  MediumInterface "tea" ""
  NamedMaterial "water"
  Shape "sphere" "float radius" [1]
  NamedMaterial "boundary"
  Shape "sphere" "float radius" [2]
AttributeEnd
AttributeBegin
  MediumInterface "" "tea"
  Material "interface"
  Shape "sphere" "float radius" [3]
AttributeEnd
NamedMaterial "boundary"
Shape "sphere" "float radius" [4]
MediumInterface "tea"
Shape "sphere" "float radius" [5]
)");
    const Json& doc = s.document;
    EXPECT_EQ(doc["media"]["tea"]["absorption"], Json::parse("[0.2, 0.6, 1.4]").get<std::vector<float>>());
    const Json& shapes = doc["shapes"];
    ASSERT_EQ(shapes.size(), 5u);  // the header's light and floor, then the three spheres that bound tea
    EXPECT_FALSE(shapes[1].contains("medium"));
    EXPECT_EQ(shapes[2]["radius"], 1.0);
    EXPECT_EQ(shapes[2]["material"], "water");
    EXPECT_EQ(shapes[2]["medium"], Json::parse(R"({"inside": "tea"})"));
    EXPECT_EQ(shapes[3]["material"], "medium boundary");
    EXPECT_EQ(shapes[4]["medium"], Json::parse(R"({"outside": "tea"})"));
    EXPECT_EQ(shapes[4]["material"], "medium boundary");
    EXPECT_EQ(doc["materials"]["medium boundary"], Json::parse(R"({"type": "dielectric", "ior": 1})"));
    // Spheres 4 (an interface bounding nothing) and 5 (tea on both sides): no boundary.
    SceneDescription d = loadImportedScene(s, scratch());
    EXPECT_EQ(d.media.size(), 1u);
}

// A medium that scatters: sigma_a and sigma_s times scale (each 1 where not given, as
// pbrt-v4's HomogeneousMedium), and the phase function's g.
TEST(PbrtImport, ScatteringMedia) {
    const ImportedScene s = import(R"(
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_s" [0.5 1 2] "float scale" [0.5] "float g" [0.3]
MakeNamedMedium "haze" "string type" "homogeneous" "rgb sigma_a" [0 0 0]
MakeNamedMaterial "boundary" "string type" "interface"
NamedMaterial "boundary"
MediumInterface "fog" ""
Shape "sphere" "float radius" [1]
MediumInterface "haze" ""
Shape "sphere" "float radius" [2]
)");
    const Json& media = s.document["media"];
    EXPECT_EQ(media["fog"], Json::parse(R"({"absorption": [0.5, 0.5, 0.5], "scattering": [0.25, 0.5, 1], "g": 0.3})"));
    EXPECT_EQ(media["haze"], Json::parse(R"({"absorption": [0, 0, 0], "scattering": [1, 1, 1]})"));
    const SceneDescription d = loadImportedScene(s, scratch());
    ASSERT_EQ(d.media.size(), 2u);
    EXPECT_EQ(d.media[0].scattering, Color(0.25f, 0.5f, 1.0f));
    EXPECT_FLOAT_EQ(d.media[0].g, 0.3f);
}

// pbrt-v4's quadrics that are not whole spheres become meshes with pbrt's parameterisation
// and the exact normals at their vertices, facing out (or in under ReverseOrientation):
// their areas within 0.05% of the surfaces' (256 segments a turn).
TEST(PbrtImport, PartialSpheresCylindersAndDisksAsMeshes) {
    const ImportedScene s = import(R"(
Shape "sphere" "float radius" [2] "float zmin" [0]
Shape "cylinder" "float radius" [0.5] "float zmin" [-1] "float zmax" [2] "float phimax" [90]
Shape "disk" "float radius" [1] "float innerradius" [0.5] "float height" [3] "float phimax" [180]
ReverseOrientation
Shape "cylinder"
)");
    const Json& shapes = s.document["shapes"];
    ASSERT_EQ(shapes.size(), 6u);
    auto meshOf = [&](size_t i) { return s.meshes.at(shapes[i]["file"].get<std::string>()); };
    auto area = [](const TriangleMesh& m) {
        double a = 0;
        for (size_t t = 0; t < m.triangleCount(); ++t) a += m.area(t);
        return a;
    };
    const double pi = 3.14159265358979323846;
    const double expected[] = {2 * pi * 4, 0.5 * pi / 2 * 3, pi / 2 * (1 - 0.25), 2 * pi * 2};
    for (size_t i = 0; i < 4; ++i) {
        const TriangleMesh m = meshOf(2 + i);
        EXPECT_NEAR(area(m), expected[i], 5e-4 * expected[i]) << "shape " << 2 + i;
        // Every triangle faces its vertex normals, which face out (the last turned in).
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const TriangleMesh::Corners k = m.corners(t);
            const Vec3 n = m.normals[m.indices[3 * t]], centre = (k.a + k.b + k.c) / 3.0f;
            ASSERT_GT(dot(cross(k.b - k.a, k.c - k.a), n), 0.0f) << "shape " << 2 + i << ", triangle " << t;
            const Vec3 out = i == 2 ? Vec3(0, 0, 1) : i == 1 || i == 3 ? Vec3(centre.x, centre.y, 0) : centre;
            ASSERT_GT(dot(n, out) * (i == 3 ? -1.0f : 1.0f), 0.0f) << "shape " << 2 + i << ", triangle " << t;
        }
    }
    // pbrt's (u, v): the hemisphere's v runs from its equator (z = 0) to its pole.
    const TriangleMesh hemisphere = meshOf(2);
    for (size_t v = 0; v < hemisphere.positions.size(); v += 97)
        EXPECT_NEAR(hemisphere.positions[v].z, 2 * std::sin(hemisphere.uvs[v].y * pi / 2), 1e-5) << v;
}

// bilinearmesh: a flat patch is its two triangles over its own four vertices; a saddle
// (corners (0,0,0), (1,0,0), (0,1,0), (1,1,1): the surface z = x y) becomes an 8 x 8 grid on
// the surface, its uvs bilinear in the corners', whose area is within 0.2% of the saddle's,
// the integral of sqrt(1 + x^2 + y^2) over the unit square, 1.280789 (two triangles: 1.414).
TEST(PbrtImport, BilinearPatchesFlatAndCurved) {
    const ImportedScene s = import(R"(
Shape "bilinearmesh" "point3 P" [0 0 0  1 0 0  0 1 0  1 1 0] "integer indices" [0 1 2 3]
Shape "bilinearmesh" "point3 P" [0 0 0  1 0 0  0 1 0  1 1 1] "integer indices" [0 1 2 3]
    "point2 uv" [0 0  1 0  0 1  1 1]
)");
    const Json& shapes = s.document["shapes"];
    const TriangleMesh flat = s.meshes.at(shapes[2]["file"].get<std::string>());
    EXPECT_EQ(flat.triangleCount(), 2u);
    EXPECT_EQ(flat.positions.size(), 4u);
    EXPECT_GT(flat.faceNormal(0).z, 0.99f);
    const TriangleMesh saddle = s.meshes.at(shapes[3]["file"].get<std::string>());
    EXPECT_EQ(saddle.triangleCount(), 128u);
    double area = 0;
    for (size_t t = 0; t < saddle.triangleCount(); ++t) {
        area += saddle.area(t);
        ASSERT_GT(saddle.faceNormal(t).z, 0.0f) << t;  // cross(dp/du, dp/dv) faces +z
    }
    EXPECT_NEAR(area, 1.280789, 2e-3 * 1.280789);
    for (size_t v = 4; v < saddle.positions.size(); ++v) {
        const Vec3 p = saddle.positions[v];
        ASSERT_NEAR(p.z, p.x * p.y, 1e-6f) << v;
        ASSERT_NEAR(saddle.uvs[v].x, p.x, 1e-6f) << v;
        ASSERT_NEAR(saddle.uvs[v].y, p.y, 1e-6f) << v;
    }
}

// Attribute: parameters for the directives of its kind that do not give their own, for the
// rest of the attribute block (pbrt-v4's GraphicsState attributes); unused ones are silent.
TEST(PbrtImport, AttributesGiveDefaultParameters) {
    const ImportedScene s = import(R"(
AttributeBegin
  Attribute "shape" "float radius" [2] "float zmin" [-5]
  Attribute "material" "rgb reflectance" [0.1 0.2 0.3]
  Attribute "light" "float scale" [3]
  Material "diffuse"
  Shape "sphere"
  Shape "sphere" "float radius" [0.5]
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Shape "sphere" "float radius" [0.25]
AttributeEnd
Shape "sphere"
)");
    const Json& shapes = s.document["shapes"];
    ASSERT_EQ(shapes.size(), 6u);
    EXPECT_EQ(shapes[2]["radius"], 2.0);
    EXPECT_EQ(shapes[3]["radius"], 0.5);
    EXPECT_EQ(shapes[4]["emission_scale"], 3.0);
    EXPECT_EQ(shapes[5]["radius"], 1.0);  // after AttributeEnd, pbrt's default
    EXPECT_EQ(s.document["materials"][shapes[2]["material"].get<std::string>()]["albedo"],
              Json::parse("[0.1, 0.2, 0.3]").get<std::vector<float>>());
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_STREQ(importError("Camera \"perspective\"\nWorldBegin\nAttribute \"camera\" \"float fov\" [10]\n").what(),
                 "bad.pbrt:3: Attribute \"camera\": the target must be \"shape\", \"light\", \"material\", \"medium\" or "
                 "\"texture\"");
}

TEST(PbrtImport, SpheresDisksInstancesAndPly) {
    TriangleMesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    tri.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    tri.indices = {0, 1, 2};  // wound to face -y: turned over to face the normals
    fs::create_directories(scratch() / "models");
    writePlyMesh(tri, scratch() / "models/tri.ply");
    ImportedScene s = import(R"(
AttributeBegin
  Translate 0 1 0
  Scale 1 2 1
  Shape "sphere" "float radius" [0.5]
AttributeEnd
Shape "disk" "float radius" [2] "float height" [0.5]
ObjectBegin "pair"
  Shape "sphere" "float radius" [0.1]
  Shape "plymesh" "string filename" "models/tri.ply"
ObjectEnd
AttributeBegin
  Translate 3 0 0
  ObjectInstance "pair"
AttributeEnd
ObjectInstance "pair"
)");
    SceneDescription d = loadImportedScene(s, scratch());
    // The unevenly scaled sphere: an object placed once; the pair: two instances.
    ASSERT_EQ(d.instances.size(), 3u);
    EXPECT_EQ(d.objects.size(), 2u);
    // The disk: radius 2 at z = 0.5, facing +z, its 256-gon 0.01% short of pi r^2.
    const ShapeDescription& disk = d.shapes[2];
    EXPECT_NEAR(disk.surfaceArea(), 4 * kPi * (1 - 1.0e-4), 4 * kPi * 1e-5);  // (N / 2 pi) sin(2 pi / N), N = 256
    EXPECT_VEC3_NEAR(disk.mesh.faceNormal(0), Vec3(0, 0, 1), 1e-5f);
    EXPECT_FLOAT_EQ(disk.mesh.positions[0].z, 0.5f);
    // The PLY, oriented to its normals, is kept in memory under a name of its own.
    const auto pair = std::find_if(d.objects.begin(), d.objects.end(), [](auto& o) { return o.name == "pair"; });
    ASSERT_NE(pair, d.objects.end());
    EXPECT_VEC3_NEAR(pair->shapes[1].mesh.faceNormal(0), Vec3(0, 1, 0), 1e-6f);
    EXPECT_TRUE(s.meshes.count("models/tri-oriented.ply"));
}

}  // namespace
}  // namespace photon
