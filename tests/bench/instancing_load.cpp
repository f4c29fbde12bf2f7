#include "instancing_load.h"
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace photon::bench {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A UV sphere of about `triangles` triangles, as OBJ text.
std::string sphereObj(int triangles) {
    const int rings = std::max(2, static_cast<int>(std::sqrt(triangles / 4.0))), segments = 2 * rings;
    std::string obj;
    char line[96];
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            double lat = M_PI * r / rings, lon = 2 * M_PI * s / segments;
            std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", std::sin(lat) * std::cos(lon), std::cos(lat),
                          std::sin(lat) * std::sin(lon));
            obj += line;
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1, c = a + segments, d = b + segments;
            std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d);
            obj += line;
        }
    return obj;
}

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

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Loads and builds the scene in a child; its timings through a pipe, its peak RSS from wait4.
json measureInChild(const fs::path& sceneFile) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        auto t0 = std::chrono::steady_clock::now();
        SceneDescription d = loadSceneFile(sceneFile);
        const double load = secondsSince(t0);
        t0 = std::chrono::steady_clock::now();
        auto scene = Scene::build(std::move(d));
        const double build = secondsSince(t0);
        double times[2] = {load, build};
        ssize_t written = write(fds[1], times, sizeof times);
        _exit(written == sizeof times ? 0 : 1);
    }
    close(fds[1]);
    double times[2] = {0, 0};
    ssize_t got = read(fds[0], times, sizeof times);
    close(fds[0]);
    int status = 0;
    rusage u{};
    wait4(pid, &status, 0, &u);
    if (got != sizeof times || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("the instancing child failed on " + sceneFile.string());
    return {{"load_seconds", times[0]}, {"build_seconds", times[1]}, {"total_seconds", times[0] + times[1]},
            {"peak_rss_kib", u.ru_maxrss}};
}

}  // namespace

json instancingLoad(int instances, int triangles) {
    const fs::path dir = fs::temp_directory_path() / ("photon-instancing-" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "mesh.obj") << sphereObj(triangles);
    std::ofstream(dir / "instanced.json") << sceneJson(instances).dump();
    std::ofstream(dir / "once.json") << sceneJson(0).dump();
    json out;
    try {
        SceneDescription probe = loadSceneFile(dir / "once.json");
        out["mesh_triangles"] = probe.shapes.at(0).mesh.triangleCount();
        out["instances"] = instances;
        out["scene_json_bytes"] = fs::file_size(dir / "instanced.json");
        out["placed_once"] = measureInChild(dir / "once.json");
        out["instanced"] = measureInChild(dir / "instanced.json");
        const double extra = out["instanced"]["peak_rss_kib"].get<double>() - out["placed_once"]["peak_rss_kib"].get<double>();
        out["extra_bytes_per_instance"] = extra * 1024.0 / instances;
    } catch (...) {
        fs::remove_all(dir);
        throw;
    }
    fs::remove_all(dir);
    return out;
}

}  // namespace photon::bench
