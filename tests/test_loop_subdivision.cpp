// pbrt-v4's loopsubdiv (import/pbrt/loop_subdivision.h): Loop's masks on one round, the
// counts of repeated rounds, the limit surface of a closed convex mesh, and the import.
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include "import/pbrt/loop_subdivision.h"
#include "import/pbrt/pbrt_import.h"
#include "test_support.h"

namespace photon {
namespace {

using pbrt::loopSubdivide;
namespace fs = std::filesystem;

// A hexagonal fan: the centre (0, 0, 1) over six ring vertices on the unit circle at z = 0.
TriangleMesh hexFan() {
    TriangleMesh m;
    m.positions.push_back({0, 0, 1});
    for (int i = 0; i < 6; ++i) m.positions.push_back({std::cos(i * kPi / 3), std::sin(i * kPi / 3), 0});
    for (uint32_t i = 0; i < 6; ++i) m.indices.insert(m.indices.end(), {0, 1 + i, 1 + (i + 1) % 6});
    return m;
}

// One round: the centre (valence 6, beta 1/16) goes to 5/8 of its height; an interior
// edge's vertex to 3/8 (a + b) + 1/8 (c + d); a boundary vertex to 3/4 v + 1/8 (its two
// boundary neighbours); a boundary edge's to its midpoint.
TEST(LoopSubdivision, OneRoundAppliesLoopsMasks) {
    const TriangleMesh m = loopSubdivide(hexFan(), 1, false);
    ASSERT_EQ(m.indices.size(), 6u * 4 * 3);
    ASSERT_EQ(m.positions.size(), 7u + 12u);
    EXPECT_VEC3_NEAR(m.positions[0], Vec3(0, 0, 0.625f), 1e-6f);
    for (int i = 1; i <= 6; ++i) {
        EXPECT_NEAR(m.positions[i].z, 0.0f, 1e-6f);
        EXPECT_NEAR(length(m.positions[i]), 0.875f, 1e-6f);  // 3/4 + 1/8 (2 cos 60)
    }
    int spokes = 0, rims = 0;
    for (size_t v = 7; v < m.positions.size(); ++v) {
        const Vec3 p = m.positions[v];
        if (std::abs(p.z - 0.375f) < 1e-6f) {
            // 3/8 (centre + ring) + 1/8 (the two ring neighbours): radius 3/8 + 1/8 (2 cos 60).
            EXPECT_NEAR(std::hypot(p.x, p.y), 0.5f, 1e-6f);
            ++spokes;
        } else {
            EXPECT_NEAR(p.z, 0.0f, 1e-6f);  // the midpoint of two ring vertices
            EXPECT_NEAR(std::hypot(p.x, p.y), std::cos(kPi / 6), 1e-6f);
            ++rims;
        }
    }
    EXPECT_EQ(spokes, 6);
    EXPECT_EQ(rims, 6);
}

// A closed octahedron, three rounds and to the limit: 8 x 64 triangles, wound outward as
// the control mesh was, normals outward. A vertex's limit position does not change with
// rounds: the octahedron's corners (valence 4: beta 3/32, gamma 1/8) go to
// (1 - 4/8) v + 1/8 (their four neighbours, which sum to 0) = v / 2 whatever the levels,
// and the rest of the surface lies nearer the centre.
TEST(LoopSubdivision, ClosedMeshGoesToASmoothLimit) {
    TriangleMesh o;
    o.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    o.indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    const TriangleMesh m = loopSubdivide(o, 3);
    ASSERT_EQ(m.triangleCount(), 8u * 64u);
    float lo = 1e9f, hi = 0;
    for (size_t v = 0; v < m.positions.size(); ++v) {
        lo = std::min(lo, length(m.positions[v]));
        hi = std::max(hi, length(m.positions[v]));
        ASSERT_GT(dot(m.normals[v], m.positions[v]), 0.9f * length(m.positions[v])) << v;
    }
    for (uint32_t corner = 0; corner < 6; ++corner)  // the control mesh's vertices keep their indices
        EXPECT_VEC3_NEAR(m.positions[corner], o.positions[corner] * 0.5f, 1e-5f);
    EXPECT_NEAR(hi, 0.5f, 1e-5f);
    EXPECT_GT(lo, 0.4f);
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const TriangleMesh::Corners k = m.corners(t);
        ASSERT_GT(dot(cross(k.b - k.a, k.c - k.a), k.a + k.b + k.c), 0.0f) << t;
    }
}

// The import: "levels" rounds (pbrt's default 3), and a refusal where they would grow past
// the bound.
TEST(LoopSubdivision, PbrtShapeImportsSubdivided) {
    const fs::path dir = fs::temp_directory_path() / ("photon-loop-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string head = R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective"
WorldBegin
LightSource "point" "rgb I" [1 1 1]
)";
    const std::string tetra = R"("point3 P" [0 0 0 1 0 0 0 1 0 0 0 1] "integer indices" [0 2 1 0 1 3 0 3 2 1 2 3])";
    std::ofstream(dir / "a.pbrt") << head << "Shape \"loopsubdiv\" \"integer levels\" [2] " << tetra << "\n";
    const ImportedScene s = importPbrt(dir / "a.pbrt");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes.begin()->second.triangleCount(), 4u * 16u);
    EXPECT_EQ(s.meshes.begin()->second.positions.size(), 34u);  // 4 + 6, then 10 + 24
    EXPECT_TRUE(s.warnings.empty());
    std::ofstream(dir / "b.pbrt") << head << "Shape \"loopsubdiv\" \"integer levels\" [12] " << tetra << "\n";
    try {
        importPbrt(dir / "b.pbrt");
        ADD_FAILURE() << "imported";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "b.pbrt:5: loopsubdiv: 12 levels of 4 triangles would make more than 16777216 (or levels < 0)");
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace photon
