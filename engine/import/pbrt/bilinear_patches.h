// pbrt-v4's "bilinearmesh": patches p(u, v) = (1-u)(1-v) p00 + u(1-v) p10 + (1-u)v p01 + uv p11
// (pbrt-v4's BilinearPatch), as triangles. A flat patch is exactly its two triangles; one
// whose corners are not in a plane is curved (a saddle) and becomes a grid on the surface.
#pragma once
#include <cstdint>
#include <vector>
#include "description/scene_description.h"

namespace photon::pbrt {

// Quads of a grid on a curved patch, each side: the grid's vertices lie on the surface, and
// an 8 x 8 grid's area is within 0.2% of a saddle's (its two triangles' 10% over it;
// tests/test_pbrt_import_shapes.cpp), the error falling as 1 / cells^2.
constexpr int kCurvedPatchCells = 8;

// `mesh` holds the vertices (positions, and normals and uvs if any, one per position);
// `indices` four per patch in pbrt's order p00, p10, p01, p11. Returns the mesh with its
// triangles: two per flat patch over its own vertices; for a curved one, new vertices on
// the surface with the corners' normals and uvs interpolated bilinearly. Winding as
// cross(dp/du, dp/dv). Throws std::length_error before the triangles would pass
// `maxTriangles`.
TriangleMesh bilinearPatches(TriangleMesh mesh, const std::vector<uint32_t>& indices, size_t maxTriangles);

}  // namespace photon::pbrt
