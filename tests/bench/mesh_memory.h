// What a large mesh costs to load and build: peak RSS per triangle, for the formats the
// engine reads itself, measured in child processes against a one-triangle mesh.
#pragma once
#include <string>
#include <nlohmann/json.hpp>

namespace photon::bench {

// Writes a sphere of about `triangles` triangles as OBJ (with and without vertex normals)
// and as binary PLY (with normals) to a temporary folder, loads and builds a scene of each
// in a child process for the seconds, renders it with photon-render (`renderBinary`) for the
// peak RSS, and reports bytes per triangle above the same scene with a one-triangle mesh.
nlohmann::json meshMemory(int triangles, const std::string& renderBinary);

}  // namespace photon::bench
