// FarmScene: a folder to a hash in Redis and back to a folder. Overrides travel as
// "key=value" lines (a value holds no newline: it is one JSON value or word).
#include "farm_scene.h"
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include "farm_keys.h"
#include "redis_client.h"

namespace photon::farm {
namespace {

constexpr std::string_view kFilePrefix = "file:";

std::string readWhole(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return std::move(out).str();
}

// A path inside the folder, or invalid_argument.
std::filesystem::path inside(const std::filesystem::path& folder, const std::string& relative) {
    const std::filesystem::path p = std::filesystem::path(relative).lexically_normal();
    if (p.empty() || p.is_absolute() || *p.begin() == ".." || p.has_root_name())
        throw std::invalid_argument("scene file path \"" + relative + "\" leaves the scene's folder");
    return folder / p;
}

}  // namespace

FarmScene FarmScene::fromFolder(const std::filesystem::path& folder, const std::string& mainFile,
                                std::vector<SettingOverride> overrides,
                                const std::function<bool(const std::filesystem::path&)>& include) {
    FarmScene s;
    s.mainFile = mainFile;
    s.overrides = std::move(overrides);
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        const std::filesystem::path relative = entry.path().lexically_relative(folder);
        if (!include || include(relative)) s.files.emplace_back(relative.generic_string(), readWhole(entry.path()));
    }
    return s;
}

SceneFile FarmScene::read(const std::filesystem::path& main) const {
    return SceneFile::read(main, overrides, ImportOptions{camera, lenient});
}

void FarmScene::store(RedisClient& redis, const std::string& job) const {
    std::string overrideLines;
    for (const SettingOverride& o : overrides) overrideLines += o.key + "=" + o.value + "\n";
    std::vector<std::string> args = {"HSET", sceneKey(job), "main", mainFile, "overrides", overrideLines, "camera", camera,
                                     "lenient", lenient ? "1" : "0"};
    for (const auto& [path, bytes] : files) {
        args.push_back(std::string(kFilePrefix) + path);
        args.push_back(bytes);
    }
    redis.command(args);
}

std::optional<FarmScene> FarmScene::load(RedisClient& redis, const std::string& job) {
    RedisReply all = redis.command({"HGETALL", sceneKey(job)});
    if (all.elements.empty()) return std::nullopt;
    FarmScene s;
    for (size_t i = 0; i + 1 < all.elements.size(); i += 2) {
        const std::string& field = all.elements[i].string;
        std::string& value = all.elements[i + 1].string;
        if (field == "main") {
            s.mainFile = value;
        } else if (field == "camera") {
            s.camera = value;
        } else if (field == "lenient") {
            s.lenient = value == "1";
        } else if (field == "overrides") {
            std::istringstream lines(value);
            for (std::string line; std::getline(lines, line);) {
                const size_t eq = line.find('=');
                if (eq != std::string::npos) s.overrides.push_back({line.substr(0, eq), line.substr(eq + 1)});
            }
        } else if (field.rfind(kFilePrefix, 0) == 0) {
            s.files.emplace_back(field.substr(kFilePrefix.size()), std::move(value));
        }
    }
    return s;
}

std::filesystem::path FarmScene::unpack(const std::filesystem::path& folder) const {
    for (const auto& [path, bytes] : files) {
        const std::filesystem::path target = inside(folder, path);
        std::filesystem::create_directories(target.parent_path());
        std::ofstream(target, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
    }
    return inside(folder, mainFile);
}

}  // namespace photon::farm
