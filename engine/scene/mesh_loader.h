// Reads triangle meshes from files: PLY (also gzipped, .ply.gz) and OBJ with the engine's own streaming readers
// (ply_mesh.h, obj_mesh.h), glTF 2.0 and whatever else Assimp knows with Assimp.
#pragma once
#include <cstddef>
#include <filesystem>
#include "description/scene_description.h"

namespace photon {

// Larger meshes are refused: they would not fit the memory budget of a render job.
constexpr size_t kMaxMeshTriangles = 10'000'000;
// A gzipped PLY ("mesh.ply.gz", as pbrt-v4 scenes ship them) is inflated in memory to at most
// this: a binary PLY of the largest mesh allowed (5M vertices with normals and uvs, 32 bytes
// each, and 10M faces of 13 bytes) is 290 MB.
constexpr size_t kMaxGzippedPlyBytes = size_t(1) << 30;

// Loads every triangle in `file`, with the file's node transforms baked in; points and
// lines are dropped. Normals are kept only if every part of the file has them (otherwise
// the renderer uses geometric normals everywhere); uvs are channel 0, (0, 0) where a part
// has none. If `confineTo` is not empty, the file and anything it references (an OBJ's
// .mtl, a glTF's .bin) must lie inside that folder. Throws std::runtime_error with the
// reason (Assimp's error text for unreadable files).
TriangleMesh loadMeshFile(const std::filesystem::path& file, const std::filesystem::path& confineTo = {});

}  // namespace photon
