#include "mesh_memory.h"
#include <filesystem>
#include <fstream>
#include "scene_load_measurement.h"
#include "scene/mesh_loader.h"
#include "scene/ply_mesh.h"

namespace photon::bench {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The mesh under a directional light, seen from outside it.
json sceneWith(const std::string& meshFile) {
    return {{"camera", {{"type", "perspective"}, {"position", {0, 0, 4}}, {"look_at", {0, 0, 0}}, {"fov", 40},
                        {"resolution", {16, 16}}}},
            {"materials", {{"grey", {{"type", "diffuse"}}}}},
            {"lights", {{{"type", "directional"}, {"direction", {0, -1, -0.3}}, {"irradiance", {3, 3, 3}}}}},
            {"shapes", {{{"type", "mesh"}, {"file", meshFile}, {"material", "grey"}}}}};
}

}  // namespace

json meshMemory(int triangles, const std::string& renderBinary) {
    return inScratchFolder("photon-mesh-memory", [&](const fs::path& dir) {
        std::ofstream(dir / "one.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        std::ofstream(dir / "smooth.obj") << sphereObj(triangles, true);
        std::ofstream(dir / "faceted.obj") << sphereObj(triangles, false);
        writePlyMesh(loadMeshFile(dir / "smooth.obj"), dir / "smooth.ply");
        const size_t count = loadMeshFile(dir / "faceted.obj").triangleCount();
        json out = {{"triangles", count}};
        auto sceneFor = [&](const std::string& meshFile) {
            const fs::path scene = dir / (meshFile + ".json");
            std::ofstream(scene) << sceneWith(meshFile).dump();
            return scene;
        };
        const double one = peakRssKibOfRender(renderBinary, sceneFor("one.obj"));
        out["one_triangle_peak_rss_kib"] = one;
        for (const char* file : {"smooth.obj", "faceted.obj", "smooth.ply"}) {
            json m = measureLoadInChild(sceneFor(file));  // the seconds
            m.erase("peak_rss_kib");
            m["file_bytes"] = fs::file_size(dir / file);
            m["peak_rss_kib"] = peakRssKibOfRender(renderBinary, sceneFor(file));
            m["bytes_per_triangle"] = (m["peak_rss_kib"].get<double>() - one) * 1024.0 / double(count);
            out[file] = m;
        }
        return out;
    });
}

}  // namespace photon::bench
