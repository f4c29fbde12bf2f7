// Loading and building a scene in a child process of its own, for what it takes: seconds
// and peak RSS; and the test mesh the load benchmarks write.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <nlohmann/json.hpp>

namespace photon::bench {

// A UV sphere of about `triangles` triangles, as OBJ text; with `normals`, a `vn` per vertex
// and faces of `v//vn` corners, as scanners and modelling tools write smooth meshes.
std::string sphereObj(int triangles, bool normals = false);

// Loads the scene file (its JSON and its meshes) and builds it (Embree) in a child process:
// {"load_seconds", "build_seconds", "total_seconds", "peak_rss_kib"}, the peak from wait4.
// Throws std::runtime_error if the child fails.
nlohmann::json measureLoadInChild(const std::filesystem::path& sceneFile);

// Runs `measure` on a new folder under the system's temporary one, named `prefix` and the
// process id, and removes the folder afterwards, whether `measure` returns or throws.
nlohmann::json inScratchFolder(const std::string& prefix,
                               const std::function<nlohmann::json(const std::filesystem::path&)>& measure);

// The peak RSS (KiB) of a fresh photon-render process (`renderBinary`) that loads, builds and
// renders the scene for one pass of one photon, its image written beside the scene. A
// process of its own from exec: a forked child starts with its parent's resident pages and
// reuses its freed heap, so its peak depends on what the parent did before. Throws
// std::runtime_error if the render fails.
double peakRssKibOfRender(const std::string& renderBinary, const std::filesystem::path& sceneFile);

}  // namespace photon::bench
