// Loading and building a scene that places one mesh many times, against the same mesh
// placed once: seconds and memory.
#pragma once
#include <nlohmann/json.hpp>

namespace photon::bench {

// Writes a scene of `instances` instances of a `triangles`-triangle mesh (an OBJ file) to
// a temporary folder, and reports, each in a child process of its own: the JSON load and
// the Embree build in seconds, and the peak RSS, for it and for the mesh placed once.
nlohmann::json instancingLoad(int instances, int triangles);

}  // namespace photon::bench
