#include "scene_load_measurement.h"
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <fcntl.h>
#include <cstdio>
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace photon::bench {

using nlohmann::json;
namespace fs = std::filesystem;

std::string sphereObj(int triangles, bool normals) {
    const int rings = std::max(2, static_cast<int>(std::sqrt(triangles / 4.0))), segments = 2 * rings;
    std::string obj;
    char line[160];  // two faces of 8-digit v//vn corners fit
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            double lat = M_PI * r / rings, lon = 2 * M_PI * s / segments;
            std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", std::sin(lat) * std::cos(lon), std::cos(lat),
                          std::sin(lat) * std::sin(lon));
            obj += line;
        }
    if (normals) {  // on the unit sphere, the normal is the position
        const size_t positionsEnd = obj.size();
        for (size_t start = 0, end; start < positionsEnd; start = end + 1) {
            end = obj.find('\n', start);
            obj += "vn" + obj.substr(start + 1, end - start);
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1, c = a + segments, d = b + segments;
            if (normals)
                std::snprintf(line, sizeof line, "f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n", a, a, c, c, b, b,
                              b, b, c, c, d, d);
            else
                std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d);
            obj += line;
        }
    return obj;
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// Its timings come back through a pipe.
json measureLoadInChild(const fs::path& sceneFile) {
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
        throw std::runtime_error("the load-measuring child failed on " + sceneFile.string());
    return {{"load_seconds", times[0]}, {"build_seconds", times[1]}, {"total_seconds", times[0] + times[1]},
            {"peak_rss_kib", u.ru_maxrss}};
}

json inScratchFolder(const std::string& prefix, const std::function<json(const fs::path&)>& measure) {
    const fs::path dir = fs::temp_directory_path() / (prefix + "-" + std::to_string(getpid()));
    fs::create_directories(dir);
    json out;
    try {
        out = measure(dir);
    } catch (...) {
        fs::remove_all(dir);
        throw;
    }
    fs::remove_all(dir);
    return out;
}

double peakRssKibOfRender(const std::string& renderBinary, const fs::path& sceneFile) {
    const std::string scene = sceneFile.string(), image = scene + ".exr";
    pid_t pid = fork();
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
        execl(renderBinary.c_str(), renderBinary.c_str(), scene.c_str(), "--passes", "1", "--photons-per-pass", "1",
              "-o", image.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage u{};
    if (pid < 0 || wait4(pid, &status, 0, &u) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("photon-render failed on " + scene);
    return double(u.ru_maxrss);
}

}  // namespace photon::bench
