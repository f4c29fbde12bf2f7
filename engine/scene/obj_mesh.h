// Wavefront OBJ triangle meshes, streamed line by line (tinyobjloader's callback reader)
// into the engine's own arrays, so that loading a mesh costs little more than the mesh:
// Assimp's importer held ~800 bytes a triangle at its peak on a 1M-triangle file
// (docs/sppm.md, "Memory").
#pragma once
#include <filesystem>
#include "description/scene_description.h"

namespace photon {

// Reads the file's `v`, `vt`, `vn` and `f` lines; polygons are fan-triangulated, faces of
// fewer than three vertices dropped; points, lines, groups, objects, materials and
// smoothing groups are ignored (the scene gives a mesh its material). A corner's (v, vt, vn)
// triple becomes one vertex, shared by every corner with the same triple. Normals are kept
// only if every corner has one; uvs if any corner has one ((0, 0) for the others). Indices
// may be negative (relative to the vertices defined so far) but must refer to vertices
// defined before the face. The positions array has room for one more element past its end,
// the padding Embree's SIMD loads need to share it. Throws std::runtime_error("OBJ: <name>:
// line N: ...") for the first problem, or when the mesh passes kMaxMeshTriangles.
TriangleMesh readObjMesh(const std::filesystem::path& file);

}  // namespace photon
