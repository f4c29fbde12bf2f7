// The mesh contract the mesh fuzz targets check: whatever a loader returns has whole
// triangles within the limit, indices in range, finite positions, and normals and uvs
// either absent or one per position. Aborts (a finding) otherwise.
#pragma once
#include <cstdint>
#include <cstdlib>
#include "description/scene_description.h"
#include "scene/mesh_loader.h"

namespace photon::fuzz {

inline void checkMesh(const TriangleMesh& mesh) {
    if (mesh.indices.size() % 3 != 0 || mesh.triangleCount() > kMaxMeshTriangles) std::abort();
    for (uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) std::abort();
    for (Vec3 p : mesh.positions)
        if (!isFinite(p)) std::abort();
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) std::abort();
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) std::abort();
}

}  // namespace photon::fuzz
