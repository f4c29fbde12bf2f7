// The engine's OBJ reader (engine/scene/obj_mesh.h): corners become shared vertices exactly
// where their (v, vt, vn) triples agree, polygons are fanned, relative indices count back,
// the example mesh reads corner for corner as Assimp's importer reads it, and every wrong
// index is an error naming the line.
#include <gtest/gtest.h>
#include <fstream>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <unistd.h>
#include "scene/mesh_loader.h"
#include "scene/obj_mesh.h"
#include "test_support.h"

namespace photon {
namespace {

namespace fs = std::filesystem;

fs::path writeObj(const std::string& name, const std::string& text) {
    const fs::path folder = fs::temp_directory_path() / ("photon-obj-test-" + std::to_string(getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / name, std::ios::binary) << text;
    return folder / name;
}

std::string errorOf(const fs::path& file) {
    try {
        readObjMesh(file);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

// One corner as the file means it: its position, uv and normal.
struct Corner {
    Vec3 p, n;
    Vec2 uv;
};
Corner cornerOf(const TriangleMesh& m, size_t k) {
    const uint32_t v = m.indices[k];
    return {m.positions[v], m.normals.empty() ? Vec3() : m.normals[v], m.uvs.empty() ? Vec2{} : m.uvs[v]};
}

TEST(ObjMesh, CornersShareAVertexOnlyWhereTheirTriplesAgree) {
    // A unit square in two triangles; the diagonal's corners share v and vn, but corner 3 of
    // the second face pairs v 3 with another uv (a texture seam), so it is a vertex of its own.
    const fs::path file = writeObj("seam.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                   "vn 0 0 1\n"
                                   "f 1/1/1 2/2/1 3/3/1\n"
                                   "f 1/1/1 3/5/1 4/4/1\n");
    const TriangleMesh m = readObjMesh(file);
    ASSERT_EQ(m.indices.size(), 6u);
    EXPECT_EQ(m.positions.size(), 5u);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 4, 3}));
    EXPECT_EQ(m.positions[4], Vec3(1, 1, 0));
    EXPECT_EQ(m.uvs[4].x, 0.5f);
    EXPECT_EQ(m.uvs[2].x, 1.0f);
    EXPECT_EQ(m.normals.size(), 5u);
    EXPECT_EQ(m.normals[4], Vec3(0, 0, 1));
    // Embree reads the last vertex with a 16-byte load: the reader leaves room for it.
    EXPECT_GE(m.positions.capacity(), m.positions.size() + 1);
    fs::remove_all(file.parent_path());
}

TEST(ObjMesh, PolygonsAreFannedAndNegativeIndicesCountBack) {
    const fs::path file = writeObj("pentagon.obj",
                                   "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\n"
                                   "f -5 -4 -3 -2 -1\n"
                                   "l 1 2\np 3\nf 1 2\n"  // a line, a point and a two-corner face: dropped
                                   "o second\ng part\nusemtl red\ns 1\n"
                                   "v 5 5 5\nf 6 1 -1\n");  // -1 is v 6 itself: a degenerate triangle, kept
    const TriangleMesh m = readObjMesh(file);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 5, 0, 5}));
    EXPECT_TRUE(m.normals.empty());
    EXPECT_TRUE(m.uvs.empty());
    fs::remove_all(file.parent_path());
}

TEST(ObjMesh, NormalsOnlyWhenEveryCornerHasOneAndUvsWhenAnyDoes) {
    const fs::path file = writeObj("mixed.obj",
                                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.25 0.75\nvn 0 0 1\n"
                                   "f 1//1 2//1 3//1\n"
                                   "f 2/1 4/1 3/1\n");
    const TriangleMesh m = readObjMesh(file);
    EXPECT_TRUE(m.normals.empty());
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    EXPECT_EQ(cornerOf(m, 0).uv.x, 0.0f);  // no uv: (0, 0)
    EXPECT_EQ(cornerOf(m, 4).uv.y, 0.75f);
    // Corners 2 and 3 of the first face have no uv, those of the second have one: v 2 and 3
    // each become two vertices.
    EXPECT_EQ(m.positions.size(), 6u);
    fs::remove_all(file.parent_path());
}

// Assimp's OBJ importer, the independent reading: the same corners in the same order.
TEST(ObjMesh, ReadsTheExampleMeshCornerForCornerAsAssimpDoes) {
    const fs::path file = photon::test::sourcePath("scenes/meshes/uv-sphere.obj");
    const TriangleMesh ours = readObjMesh(file);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate);
    ASSERT_NE(scene, nullptr);
    ASSERT_EQ(scene->mNumMeshes, 1u);
    const aiMesh& a = *scene->mMeshes[0];
    ASSERT_TRUE(a.HasNormals() && a.HasTextureCoords(0));
    ASSERT_EQ(ours.triangleCount(), a.mNumFaces);
    ASSERT_EQ(ours.normals.size(), ours.positions.size());
    for (unsigned f = 0; f < a.mNumFaces; ++f)
        for (int k = 0; k < 3; ++k) {
            const unsigned i = a.mFaces[f].mIndices[k];
            const Corner c = cornerOf(ours, 3 * f + k);
            ASSERT_EQ(c.p, Vec3(a.mVertices[i].x, a.mVertices[i].y, a.mVertices[i].z)) << "face " << f;
            ASSERT_EQ(c.n, Vec3(a.mNormals[i].x, a.mNormals[i].y, a.mNormals[i].z)) << "face " << f;
            ASSERT_EQ(c.uv.x, a.mTextureCoords[0][i].x) << "face " << f;
            ASSERT_EQ(c.uv.y, a.mTextureCoords[0][i].y) << "face " << f;
        }
}

TEST(ObjMesh, AWrongIndexIsAnErrorNamingTheLine) {
    const std::string head = "# three vertices\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n";
    EXPECT_EQ(errorOf(writeObj("a.obj", head + "f 1 2 9\n")),
              "OBJ: a.obj: line 6: a face refers to vertex 9, but 3 are defined before it");
    EXPECT_EQ(errorOf(writeObj("b.obj", head + "f 1 2 3\n\nf -4 1 2\n")),
              "OBJ: b.obj: line 8: a face refers to vertex -4, but 3 are defined before it");
    EXPECT_EQ(errorOf(writeObj("c.obj", head + "f 1//1 2//2 3//1\n")),
              "OBJ: c.obj: line 6: a face refers to normal 2, but 1 are defined before it");
    EXPECT_EQ(errorOf(writeObj("d.obj", head + "f 1/1 2/1 3/1\n")),
              "OBJ: d.obj: line 6: a face refers to texture coordinate 1, but 0 are defined before it");
    EXPECT_EQ(errorOf(writeObj("e.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n")),
              "OBJ: e.obj: line 1: a face refers to vertex 1, but 0 are defined before it");
    EXPECT_EQ(errorOf(writeObj("f.obj", head + "f x y z\n")),
              "OBJ: f.obj: line 6: a face corner has no vertex index");
    EXPECT_EQ(errorOf(writeObj("g.obj", head + "\r\nf 1 2 3\r\nf 1 2 4\r\n")),
              "OBJ: g.obj: line 8: a face refers to vertex 4, but 3 are defined before it");
    EXPECT_EQ(errorOf(fs::temp_directory_path() / "photon-no-such-mesh.obj"),
              "OBJ: photon-no-such-mesh.obj: cannot open the file");
    fs::remove_all(writeObj("x.obj", "").parent_path());
}

// The scene names the material: `mtllib` opens nothing, wherever it points; and the file
// itself must be inside the folder the scene confines it to.
TEST(ObjMesh, OpensNoOtherFileAndStaysInItsFolder) {
    const fs::path file = writeObj("lib.obj", "mtllib ../../../../etc/passwd\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(loadMeshFile(file, file.parent_path()).triangleCount(), 1u);
    const fs::path inner = file.parent_path() / "inner";
    fs::create_directories(inner);
    try {
        loadMeshFile(file, inner);
        FAIL() << "read a file outside the folder";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "OBJ: " + file.string() + ": the file is outside the folder it must be in");
    }
    fs::remove_all(file.parent_path());
}

}  // namespace
}  // namespace photon
