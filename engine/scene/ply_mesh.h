// photon's own reader and writer of PLY triangle meshes (Greg Turk, "The PLY Polygon File
// Format"), so that mesh files from untrusted scenes are read by code that checks every
// count against the bytes that are there before it allocates anything.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include "description/scene_description.h"

namespace photon {

// Reads a PLY file (ascii, binary_little_endian, binary_big_endian) into triangles: vertex
// x y z, optional nx ny nz and one pair of texture coordinates (u v, s t, texture_u
// texture_v or texture_s texture_t); the faces' `vertex_indices` (or `vertex_index`) lists,
// polygons fan-triangulated, faces of fewer than three vertices dropped. Every other
// element and property is skipped. Normals are kept as the file has them (even zero).
// Throws std::runtime_error("PLY: <name>: ...") naming the header line, or the element and
// the line or byte offset, of the first problem.
TriangleMesh readPlyMesh(const std::filesystem::path& file);
// The same from bytes in memory; `name` only for messages.
TriangleMesh readPlyMesh(std::string_view bytes, const std::string& name);

// Writes binary little-endian PLY: float x y z [nx ny nz] [u v], and faces as lists of
// uchar count and uint vertex_indices. Throws std::runtime_error if the file cannot be
// written or the mesh is inconsistent (normals or uvs not one per position).
void writePlyMesh(const TriangleMesh& mesh, const std::filesystem::path& file);

}  // namespace photon
