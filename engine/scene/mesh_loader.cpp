#include "scene/mesh_loader.h"
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include "scene/gzip_file.h"
#include "scene/obj_mesh.h"
#include "scene/ply_mesh.h"
#include "scene/scene_paths.h"

namespace photon {

namespace {

// Assimp opens the files a mesh references (.mtl, .bin) by itself; this IO system lets it
// open only files inside the scene folder, and only for reading.
class ConfinedIOSystem : public Assimp::DefaultIOSystem {
public:
    explicit ConfinedIOSystem(std::filesystem::path root) : root_(std::move(root)) {}
    bool Exists(const char* file) const override {
        return isInsideFolder(file, root_) && DefaultIOSystem::Exists(file);
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::strpbrk(mode, "wa+") || !isInsideFolder(file, root_)) return nullptr;
        return DefaultIOSystem::Open(file, mode);
    }

private:
    std::filesystem::path root_;
};

// Appends one Assimp mesh (triangles only). `withNormals` / `withUvs` say whether the
// combined mesh carries those arrays, so every part fills them the same way.
void appendMesh(const aiMesh& m, bool withNormals, bool withUvs, TriangleMesh& out) {
    auto base = static_cast<uint32_t>(out.positions.size());
    for (unsigned i = 0; i < m.mNumVertices; ++i) {
        const aiVector3D& p = m.mVertices[i];
        out.positions.push_back({p.x, p.y, p.z});
        if (withNormals) out.normals.push_back({m.mNormals[i].x, m.mNormals[i].y, m.mNormals[i].z});
        if (withUvs) {
            Vec2 uv = m.HasTextureCoords(0) ? Vec2{m.mTextureCoords[0][i].x, m.mTextureCoords[0][i].y} : Vec2{};
            out.uvs.push_back(uv);
        }
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const aiFace& face = m.mFaces[f];
        if (face.mNumIndices != 3) continue;  // a stray point or line SortByPType kept
        for (int k = 0; k < 3; ++k) {
            if (face.mIndices[k] >= m.mNumVertices) throw std::runtime_error("face index out of range");
            out.indices.push_back(base + face.mIndices[k]);
        }
    }
}

// Normals that are zero or not finite would poison shading; a file with any such normal
// is rendered with geometric normals instead. Non-finite uvs become (0, 0).
void sanitize(TriangleMesh& mesh) {
    for (Vec3 p : mesh.positions)
        if (!isFinite(p)) throw std::runtime_error("mesh has a vertex position that is not a finite number");
    for (Vec3& n : mesh.normals) {
        float len = length(n);
        if (!std::isfinite(len) || len == 0) {
            mesh.normals = {};  // freed, not just emptied
            break;
        }
        n = n / len;
    }
    for (Vec2& uv : mesh.uvs)
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = {};
}

// PLY and OBJ are read by the engine's own streaming readers (ply_mesh.h, obj_mesh.h): the
// PLY reader checks every count in the file against its size, the OBJ reader holds little
// more than the mesh. Neither opens another file (an OBJ's `mtllib` is not read: the scene
// gives the mesh its material), so only the file itself is confined.
TriangleMesh loadOwnFormat(const std::filesystem::path& file, const std::filesystem::path& confineTo, bool ply) {
    if (!confineTo.empty() && !isInsideFolder(file, confineTo))
        throw std::runtime_error(std::string(ply ? "PLY: " : "OBJ: ") + file.string() +
                                 ": the file is outside the folder it must be in");
    TriangleMesh mesh = ply ? readPlyMesh(file) : readObjMesh(file);
    if (mesh.indices.empty()) throw std::runtime_error("the file contains no triangles");
    sanitize(mesh);
    return mesh;
}

// pbrt-v4's "mesh.ply.gz": read whole, inflated in memory (at most kMaxGzippedPlyBytes), then
// read as PLY.
TriangleMesh loadGzippedPly(const std::filesystem::path& file, const std::filesystem::path& confineTo) {
    if (!confineTo.empty() && !isInsideFolder(file, confineTo))
        throw std::runtime_error("PLY: " + file.string() + ": the file is outside the folder it must be in");
    std::ifstream in(file, std::ios::binary);
    const std::string compressed{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.eof() && in.fail()) throw std::runtime_error("PLY: " + file.string() + ": cannot read the file");
    TriangleMesh mesh = readPlyMesh(gunzip(compressed, kMaxGzippedPlyBytes, "PLY: " + file.string()), file.string());
    if (mesh.indices.empty()) throw std::runtime_error("the file contains no triangles");
    sanitize(mesh);
    return mesh;
}

}  // namespace

TriangleMesh loadMeshFile(const std::filesystem::path& file, const std::filesystem::path& confineTo) {
    const std::string extension = lowerCaseExtension(file);
    if (extension == ".ply" || extension == ".obj") return loadOwnFormat(file, confineTo, extension == ".ply");
    if (extension == ".gz" && lowerCaseExtension(file.stem()) == ".ply") return loadGzippedPly(file, confineTo);
    Assimp::Importer importer;
    if (!confineTo.empty()) importer.SetIOHandler(new ConfinedIOSystem(confineTo));  // importer owns it
    // Drop points and lines at SortByPType: the renderer only intersects triangles.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                           aiProcess_SortByPType | aiProcess_FindInvalidData | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(file.string(), flags);
    if (!scene) throw std::runtime_error(importer.GetErrorString());
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw std::runtime_error("the file is incomplete");

    size_t triangles = 0, vertices = 0;
    bool allNormals = true, anyUvs = false;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        triangles += m.mNumFaces;
        vertices += m.mNumVertices;
        allNormals = allNormals && m.HasNormals();
        anyUvs = anyUvs || m.HasTextureCoords(0);
    }
    if (triangles == 0) throw std::runtime_error("the file contains no triangles");
    if (triangles > kMaxMeshTriangles)
        throw std::runtime_error("the mesh has " + std::to_string(triangles) + " triangles, more than the limit of " +
                                 std::to_string(kMaxMeshTriangles));

    TriangleMesh mesh;
    mesh.positions.reserve(vertices);
    mesh.indices.reserve(triangles * 3);
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) appendMesh(m, allNormals, anyUvs, mesh);
    }
    sanitize(mesh);
    return mesh;
}

}  // namespace photon
