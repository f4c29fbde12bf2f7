// Curves (docs/scene-format.md#curves): Embree's tubes and ribbons against the analytic
// hit of a straight fibre, the bases' formulas against Embree's curves, the filter that
// keeps a ray off the fibre it leaves, the HAIR file format, the JSON shape and pbrt-v4's
// "curve" import (B-splines and quadratics made Bezier exactly, widths, merging).
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include "description/curve_set.h"
#include "import/pbrt/pbrt_import.h"
#include "math/ray.h"
#include "pbrt_import_fixture.h"
#include "scene/hair_file.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"

namespace photon {
namespace {

namespace fs = std::filesystem;
using namespace test::pbrt_import;

// One strand of `points` with radius r each, of material 0.
ShapeDescription strand(std::vector<Vec3> points, float r, CurveBasis basis, CurveProfile profile) {
    ShapeDescription s;
    s.kind = ShapeDescription::Kind::Curves;
    s.curves.basis = basis;
    s.curves.profile = profile;
    s.curves.strandStarts = {0};
    for (Vec3 p : points) s.curves.points.push_back({p, r});
    s.name = "strand";
    return s;
}

// A straight Bezier fibre along x from -1 to 1 (control points at thirds, so u is linear
// in x), radius 0.1, at height y = z = zOffset.
ShapeDescription straightFibre(CurveProfile profile, float z = 0) {
    return strand({{-1, 0, z}, {-1.0f / 3, 0, z}, {1.0f / 3, 0, z}, {1, 0, z}}, 0.1f, CurveBasis::Bezier, profile);
}

std::shared_ptr<const Scene> sceneOf(std::vector<ShapeDescription> shapes) {
    SceneDescription d = test::hitTestScene();
    d.shapes = std::move(shapes);
    return Scene::build(std::move(d));
}

// A ray down -z at offset y across a round fibre of radius r meets its wall at depth
// sqrt(r^2 - y^2) before the axis, where the normal is (0, y, sqrt(r^2 - y^2)) / r; v runs
// across the width as seen, (y / r + 1) / 2, and u along the strand.
TEST(Curves, RoundFibreIsHitWhereTheCylinderIs) {
    auto scene = sceneOf({straightFibre(CurveProfile::Round)});
    const float r = 0.1f;
    for (float x : {-0.5f, 0.25f})
        for (float y : {0.0f, 0.05f, -0.08f}) {
            SCOPED_TRACE("x " + std::to_string(x) + ", y " + std::to_string(y));
            SurfaceHit hit;
            ASSERT_TRUE(scene->intersect(Ray{{x, y, 5}, {0, 0, -1}}, hit));
            const float depth = std::sqrt(r * r - y * y);
            EXPECT_NEAR(hit.t, 5 - depth, 2e-4f);
            EXPECT_NEAR(hit.ng.y, y / r, 2e-3f);
            EXPECT_NEAR(hit.ng.z, depth / r, 2e-3f);
            EXPECT_NEAR(hit.uv.x, (x + 1) / 2, 1e-3f);
            EXPECT_NEAR(hit.uv.y, (y / r + 1) / 2, 2e-3f);
        }
    SurfaceHit miss;
    EXPECT_FALSE(scene->intersect(Ray{{0, 0.11f, 5}, {0, 0, -1}}, miss));
}

// A flat fibre is a ribbon through the axis turned to face the ray: met at the axis's
// depth, its normal toward the ray, with the same v across it.
TEST(Curves, FlatFibreFacesTheRay) {
    auto scene = sceneOf({straightFibre(CurveProfile::Flat)});
    for (float y : {0.0f, 0.06f, -0.09f}) {
        SurfaceHit hit;
        ASSERT_TRUE(scene->intersect(Ray{{0.3f, y, 5}, {0, 0, -1}}, hit));
        EXPECT_NEAR(hit.t, 5, 1e-3f);
        EXPECT_NEAR(hit.ng.z, 1, 1e-4f);
        EXPECT_NEAR(hit.uv.y, (y / 0.1f + 1) / 2, 2e-3f);
    }
    // Seen from a slant the ribbon still faces the ray.
    const Vec3 d = normalize(Vec3(0, 0.6f, -1));
    SurfaceHit hit;
    ASSERT_TRUE(scene->intersect(Ray{Vec3(0, 0, 0) - d * 5, d}, hit));
    EXPECT_NEAR(dot(hit.ng, -d), 1, 1e-3f);
}

// A ray that leaves a fibre, whichever way (through it, too), does not meet that fibre
// again, neither as a hit nor as an occluder; a fibre behind it still stops it.
TEST(Curves, RayLeavingAFibreSkipsItButNotItsNeighbour) {
    for (CurveProfile profile : {CurveProfile::Round, CurveProfile::Flat}) {
        SCOPED_TRACE(profile == CurveProfile::Round ? "round" : "flat");
        auto alone = sceneOf({straightFibre(profile)});
        auto pair = sceneOf({straightFibre(profile), straightFibre(profile, -1.0f)});
        for (float y : {0.0f, 0.07f}) {
            SurfaceHit hit;
            ASSERT_TRUE(alone->intersect(Ray{{0.2f, y, 5}, {0, 0, -1}}, hit));
            for (Vec3 w : {Vec3(0, 0, -1), normalize(Vec3(0.3f, -0.5f, -1)), normalize(Vec3(0.9f, 0.1f, -0.2f)),
                           normalize(Vec3(0, 1, 0.2f)), Vec3(0, 0, 1)}) {
                const Ray out = spawnRay(hit.p, hit.ng, w);
                SurfaceHit again;
                EXPECT_FALSE(alone->intersect(out, again)) << "direction " << w.x << " " << w.y << " " << w.z;
                EXPECT_FALSE(alone->occluded(out));
            }
            SurfaceHit first, behind;
            ASSERT_TRUE(pair->intersect(Ray{{0.2f, y, 5}, {0, 0, -1}}, first));
            ASSERT_TRUE(pair->intersect(spawnRay(first.p, first.ng, {0, 0, -1}), behind));
            EXPECT_NEAR(behind.p.z, profile == CurveProfile::Round ? -1 + std::sqrt(0.01f - y * y) : -1.0f, 2e-3f);
        }
    }
}

// evaluateCurve's basis functions are Embree's: aimed at the centre line evaluateCurve gives
// at u, a ray down -z meets a round curve of every basis one radius from the centre line
// evaluateCurve gives at the u Embree reports, and near u.
TEST(Curves, BasesAgreeWithEmbree) {
    const std::vector<Vec3> wave = {{-1.5f, 0, 0}, {-1, 0.4f, 0.1f}, {-0.5f, -0.3f, 0}, {0, 0.5f, -0.2f},
                                    {0.5f, -0.2f, 0.1f}, {1, 0.3f, 0}, {1.5f, 0, 0.2f}};
    for (CurveBasis basis : {CurveBasis::Bezier, CurveBasis::BSpline, CurveBasis::CatmullRom, CurveBasis::Linear}) {
        SCOPED_TRACE("basis " + std::to_string(int(basis)));
        const float r = 0.02f;
        auto scene = sceneOf({strand(wave, r, basis, CurveProfile::Round)});
        const CurveSegments segments = makeCurveSegments(scene->shape(0).curves);
        ASSERT_EQ(segments.firstPoint.size(), CurveSet::segmentsOf(basis, wave.size()));
        for (size_t j = 0; j < segments.firstPoint.size(); ++j)
            for (float u : {0.2f, 0.5f, 0.8f}) {
                const CurvePoint* points = &scene->shape(0).curves.points[segments.firstPoint[j]];
                const CurveSample c = evaluateCurve(basis, points, u);
                SurfaceHit hit;
                ASSERT_TRUE(scene->intersect(Ray{c.center + Vec3(0, 0, 5), {0, 0, -1}}, hit)) << "segment " << j << ", u " << u;
                ASSERT_EQ(hit.primitive, j);
                const CurveSample at = evaluateCurve(basis, points, hit.barycentric.x);
                EXPECT_NEAR(length(hit.p - at.center), r, 0.05f * r) << "segment " << j << ", u " << u;
                EXPECT_NEAR(hit.barycentric.x, u, 0.05f);
            }
    }
}

TEST(HairFile, RoundTripsStrandsAndRefusesBrokenFiles) {
    CurveSet c;
    c.strandStarts = {0, 4};
    for (int i = 0; i < 6; ++i) c.points.push_back({{float(i), float(i * i), -float(i)}, 0.01f * float(i + 1)});
    const std::string bytes = hairFileBytes(c);
    EXPECT_EQ(bytes.size(), 128u + 2 * 2 + 6 * 12 + 6 * 4);
    const CurveSet back = readHairFile(std::string_view(bytes), "x.hair", 0.0f);
    EXPECT_EQ(back.strandStarts, c.strandStarts);
    ASSERT_EQ(back.points.size(), c.points.size());
    for (size_t i = 0; i < c.points.size(); ++i) {
        EXPECT_EQ(back.points[i].p, c.points[i].p);
        EXPECT_FLOAT_EQ(back.points[i].radius, c.points[i].radius);
    }
    auto error = [](const std::string& b) {
        try {
            readHairFile(std::string_view(b), "x.hair", 0.0f);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error(bytes.substr(0, 100)), "HAIR: x.hair: shorter than the 128-byte header");
    EXPECT_EQ(error("HAIX" + bytes.substr(4)), "HAIR: x.hair: does not start with the signature HAIR");
    EXPECT_EQ(error(bytes.substr(0, bytes.size() - 1)), "HAIR: x.hair: is 227 bytes, its header's counts need 228");
    std::string wrongCount = bytes;
    wrongCount[128] = 4;  // the first strand's 3 segments become 4: 7 points of 6
    EXPECT_EQ(error(wrongCount), "HAIR: x.hair: strand 1 runs past the header's 6 points");
}

// The scene's folder, with a HAIR file in it.
fs::path curvesFolder() {
    const fs::path dir = scratch() / "curves";
    fs::create_directories(dir);
    CurveSet c;
    c.strandStarts = {0};
    for (int i = 0; i < 4; ++i) c.points.push_back({{float(i) / 3 - 0.5f, 1, 0}, 0.005f});
    writeHairFile(c, dir / "strands.hair");
    return dir;
}

std::string sceneWith(const std::string& shape, const std::string& integrator = "sppm") {
    return R"({"camera": {"position": [0, 1, 4], "look_at": [0, 1, 0], "fov": 30, "resolution": [16, 16]},
      "materials": {"hair": {"type": "hair", "eumelanin": 0.5}, "grey": {"type": "diffuse"}},
      "shapes": [{"type": "quad", "origin": [-1, 2, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "material": "grey",
                  "emission": [1, 1, 1], "flip_normals": true}, )" +
           shape + R"(], "render": {"integrator": ")" + integrator + R"("}})";
}

std::string loadError(const std::string& text, const fs::path& dir) {
    try {
        loadSceneJson(text, dir);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

TEST(CurvesJson, ReadsStrandsFromFileOrInlineAndNamesWhatIsWrong) {
    const fs::path dir = curvesFolder();
    SceneDescription d = loadSceneJson(
        sceneWith(R"({"type": "curves", "file": "strands.hair", "basis": "bezier", "width": 0.02, "material": "hair",
                      "transform": {"translate": [0, 0.5, 0]}})"),
        dir);
    ASSERT_EQ(d.shapes.size(), 2u);
    const CurveSet& c = d.shapes[1].curves;
    EXPECT_EQ(c.basis, CurveBasis::Bezier);
    EXPECT_EQ(c.profile, CurveProfile::Round);
    ASSERT_EQ(c.points.size(), 4u);
    EXPECT_FLOAT_EQ(c.points[3].p.y, 1.5f);
    EXPECT_FLOAT_EQ(c.points[3].radius, 0.005f);  // the file's thickness, not "width"
    EXPECT_EQ(d.files, std::vector<std::string>{"strands.hair"});
    d = loadSceneJson(sceneWith(R"({"type": "curves", "strands": [[[0, 0, 0, 0.1], [1, 0, 0]], [[0, 1, 0], [0, 2, 0]]],
                                   "width": 0.04, "profile": "flat", "material": "hair"})"),
                      dir);
    EXPECT_EQ(d.shapes[1].curves.basis, CurveBasis::Linear);
    EXPECT_EQ(d.shapes[1].curves.strandStarts, (std::vector<uint32_t>{0, 2}));
    EXPECT_FLOAT_EQ(d.shapes[1].curves.points[0].radius, 0.05f);
    EXPECT_FLOAT_EQ(d.shapes[1].curves.points[1].radius, 0.02f);

    EXPECT_EQ(loadError(sceneWith(R"({"type": "curves", "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0]]], "width": 0.1,
                                     "basis": "bezier", "material": "hair"})"),
                        dir),
              "shapes[1]: strand 0 has 3 points; a Bezier strand needs 3k + 1 points (k >= 1)");
    EXPECT_EQ(loadError(sceneWith(R"({"type": "curves", "strands": [[[0, 0, 0], [1, 0, 0]]], "material": "hair"})"), dir),
              "shapes[1]: needs \"width\" for points given without one");
    EXPECT_EQ(loadError(sceneWith(R"({"type": "curves", "strands": [[[0, 0, 0], [1, 0, 0]]], "width": 0.1,
                                     "emission": [1, 1, 1], "material": "hair"})"),
                        dir),
              "shapes[1].emission: curves cannot have \"emission\"");
    EXPECT_EQ(loadError(sceneWith(R"({"type": "curves", "strands": [[[0, 0, 0, 0], [1, 0, 0, 0]]], "material": "hair"})"), dir),
              "shapes[1]: every point has width 0 (give \"width\", or thicknesses in the file)");
    EXPECT_EQ(loadError(sceneWith(R"({"type": "curves", "strands": [[[0, 0, 0], [1, 0, 0]]], "width": 0.1,
                                     "material": "hair"})",
                                  "radiosity"),
                        dir),
              "shapes[1]: curves are rendered by the \"sppm\" and \"path\" integrators only");
}

// pbrt-v4's hair reads its reflectance as "reflectance", or as "color", its older name.
TEST(PbrtCurves, HairTakesItsColourByEitherName) {
    for (const char* name : {"reflectance", "color"}) {
        const ImportedScene s = import(std::string("Material \"hair\" \"rgb ") + name + R"(" [0.3 0.2 0.1]
Shape "curve" "point3 P" [0 0 0  1 1 0  2 1 0  3 0 0] "float width" [0.02] "string type" "cylinder"
)");
        const Json& curves = s.document["shapes"][2];
        const Json& material = s.document["materials"][curves["material"].get<std::string>()];
        ASSERT_TRUE(material.contains("color")) << name;
        EXPECT_NEAR(material["color"][0].get<double>(), 0.3, 1e-6) << name;
        EXPECT_NEAR(material["color"][2].get<double>(), 0.1, 1e-6) << name;
        EXPECT_TRUE(s.warnings.empty()) << name;
    }
}

// Three pbrt curves: a cubic Bezier, a cubic B-spline of 5 points (2 segments) and a
// quadratic Bezier, all of the same material and type: one "curves" shape whose HAIR file
// holds three Bezier strands that trace the same curves, widths running from width0 to
// width1.
TEST(PbrtCurves, BecomeOneShapeOfBezierStrands) {
    const ImportedScene s = import(R"(
Material "hair" "float eumelanin" [0.7] "float beta_m" [0.25]
Shape "curve" "point3 P" [0 0 0  1 1 0  2 1 0  3 0 0] "float width0" [0.1] "float width1" [0.04] "string type" "cylinder"
Shape "curve" "string basis" "bspline" "point3 P" [0 0 1  1 2 1  2 -1 1  3 1 1  4 0 1] "float width" [0.02] "string type" "cylinder"
Shape "curve" "integer degree" [2] "point3 P" [0 0 2  1 2 2  2 0 2] "float width" [0.02] "string type" "cylinder"
)");
    const Json& shapes = s.document["shapes"];
    ASSERT_EQ(shapes.size(), 3u);  // the light, the floor, the curves
    const Json& curves = shapes[2];
    EXPECT_EQ(curves["type"], "curves");
    EXPECT_EQ(curves["basis"], "bezier");
    EXPECT_EQ(curves["profile"], "round");
    const Json& material = s.document["materials"][curves["material"].get<std::string>()];
    EXPECT_EQ(material, (Json{{"type", "hair"}, {"eumelanin", 0.7}, {"beta_m", 0.25}}));
    const std::string file = curves["file"];
    ASSERT_TRUE(s.files.count(file));
    const CurveSet c = readHairFile(std::string_view(s.files.at(file)), file, 0.0f);
    ASSERT_EQ(c.strandStarts, (std::vector<uint32_t>{0, 4, 11}));
    EXPECT_EQ(c.points.size(), 15u);
    EXPECT_FLOAT_EQ(c.points[0].radius, 0.05f);
    EXPECT_FLOAT_EQ(c.points[3].radius, 0.02f);
    EXPECT_NEAR(c.points[1].radius, 0.04f, 1e-6f);
    // The B-spline's second segment at u, from its own basis, against the Bezier strand's.
    const CurvePoint bspline[4] = {{{1, 2, 1}, 0}, {{2, -1, 1}, 0}, {{3, 1, 1}, 0}, {{4, 0, 1}, 0}};
    for (float u : {0.0f, 0.3f, 1.0f}) {
        const Vec3 want = evaluateCurve(CurveBasis::BSpline, bspline, u).center;
        const Vec3 got = evaluateCurve(CurveBasis::Bezier, &c.points[4 + 3], u).center;
        EXPECT_NEAR(length(want - got), 0, 1e-5f) << "u " << u;
    }
    // The quadratic through its Bezier cubic: q(u) = (1-u)^2 q0 + 2u(1-u) q1 + u^2 q2.
    const Vec3 q0{0, 0, 2}, q1{1, 2, 2}, q2{2, 0, 2};
    for (float u : {0.25f, 0.5f}) {
        const Vec3 want = q0 * ((1 - u) * (1 - u)) + q1 * (2 * u * (1 - u)) + q2 * (u * u);
        EXPECT_NEAR(length(evaluateCurve(CurveBasis::Bezier, &c.points[11], u).center - want), 0, 1e-5f);
    }
    // The scene it makes renders (the JSON loader reads the file from memory).
    const SceneDescription loaded = loadImportedScene(s, scratch());
    EXPECT_EQ(loaded.shapes.back().curves.points.size(), 15u);
}

// Curves inside ObjectBegin become the object's shape; an instance scaled by 2 doubles the
// tube: a ray down -z meets it 2 r before its axis (r = 0.05).
TEST(PbrtCurves, InstancedCurvesScaleWithTheirInstance) {
    const ImportedScene s = import(R"(
Material "hair"
ObjectBegin "tuft"
Shape "curve" "point3 P" [-1 0 0  -0.3 0 0  0.3 0 0  1 0 0] "float width" [0.1] "string type" "cylinder"
ObjectEnd
AttributeBegin
  Translate 0 3 0
  ObjectInstance "tuft"
AttributeEnd
AttributeBegin
  Translate 0 6 0
  Scale 2 2 2
  ObjectInstance "tuft"
AttributeEnd
)");
    EXPECT_EQ(s.document["objects"]["tuft"]["shapes"][0]["type"], "curves");
    auto scene = Scene::build(loadImportedScene(s, scratch()));
    for (auto [y, r] : {std::pair{3.0f, 0.05f}, {6.0f, 0.1f}}) {
        SurfaceHit hit;
        ASSERT_TRUE(scene->intersect(Ray{{0.2f, y, 5}, {0, 0, -1}}, hit)) << "y " << y;
        EXPECT_NEAR(hit.t, 5 - r, 1e-3f) << "y " << y;
        EXPECT_NEAR(hit.ng.z, 1, 1e-3f);
        EXPECT_NEAR(hit.uv.y, 0.5f, 2e-3f);
    }
}

TEST(PbrtCurves, RibbonsAreRefusedUnlessLenientAndBadCurvesNamed) {
    const std::string ribbon = kHeader + R"(Material "hair"
Shape "curve" "point3 P" [0 0 0  1 1 0  2 1 0  3 0 0] "string type" "ribbon" "normal N" [0 0 1  0 0 1]
)";
    EXPECT_NE(std::string(importError(ribbon).what()).find("ribbons oriented by \"N\" are not supported"), std::string::npos);
    const ImportedScene lenient = importPbrt(writeScene("ribbon.pbrt", ribbon), true);
    EXPECT_EQ(lenient.document["shapes"][2]["profile"], "flat");
    const SceneError e = importError(kHeader + R"(Shape "curve" "point3 P" [0 0 0  1 1 0  2 1 0  3 0 0  4 0 0])");
    EXPECT_NE(std::string(e.what()).find("\"P\" must hold 3k + 1 points (k >= 1)"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace photon
