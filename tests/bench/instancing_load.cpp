#include "instancing_load.h"
#include <cmath>
#include <filesystem>
#include <fstream>
#include "scene_load_measurement.h"
#include "scene/scene_loader.h"

namespace photon::bench {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The scene: the mesh as an object placed on a square grid with varied rotations and
// scales (instances > 0), or placed once as an ordinary shape (instances == 0).
json sceneJson(int instances) {
    json d = {{"camera", {{"type", "perspective"}, {"position", {0, 50, 150}}, {"look_at", {0, 0, 0}},
                          {"fov", 40}, {"resolution", {64, 64}}}},
              {"materials", {{"grey", {{"type", "diffuse"}}}}},
              {"lights", {{{"type", "directional"}, {"direction", {0, -1, -0.3}}, {"irradiance", {3, 3, 3}}}}}};
    json mesh = {{"type", "mesh"}, {"file", "mesh.obj"}, {"material", "grey"}};
    if (instances == 0) {
        d["shapes"] = json::array({mesh});
        return d;
    }
    d["objects"] = {{"ball", {{"shapes", json::array({mesh})}}}};
    const int side = static_cast<int>(std::ceil(std::sqrt(instances)));
    json shapes = json::array();
    for (int i = 0; i < instances; ++i) {
        json t = {{"scale", 0.3 + 0.1 * (i % 5)},
                  {"rotate", {{"axis", {1, i % 3, 2}}, {"angle", (i * 37) % 360}}},
                  {"translate", {2.0 * (i % side - side / 2), 0, 2.0 * (i / side - side / 2)}}};
        shapes.push_back({{"type", "instance"}, {"object", "ball"}, {"transform", t}});
    }
    d["shapes"] = shapes;
    return d;
}

}  // namespace

json instancingLoad(int instances, int triangles) {
    return inScratchFolder("photon-instancing", [&](const fs::path& dir) {
        std::ofstream(dir / "mesh.obj") << sphereObj(triangles);
        std::ofstream(dir / "instanced.json") << sceneJson(instances).dump();
        std::ofstream(dir / "once.json") << sceneJson(0).dump();
        json out;
        SceneDescription probe = loadSceneFile(dir / "once.json");
        out["mesh_triangles"] = probe.shapes.at(0).mesh.triangleCount();
        out["instances"] = instances;
        out["scene_json_bytes"] = fs::file_size(dir / "instanced.json");
        out["placed_once"] = measureLoadInChild(dir / "once.json");
        out["instanced"] = measureLoadInChild(dir / "instanced.json");
        const double extra =
            out["instanced"]["peak_rss_kib"].get<double>() - out["placed_once"]["peak_rss_kib"].get<double>();
        out["extra_bytes_per_instance"] = extra * 1024.0 / instances;
        return out;
    });
}

}  // namespace photon::bench
