// A job's scene as the farm carries it: its main file's name, the files beside it by their
// paths relative to the scene's folder, and the setting overrides on top. The coordinator
// stores it in Redis once per job; each worker unpacks it into a folder of its own.
#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include <photon/scene_file.h>

namespace photon::farm {

class RedisClient;

struct FarmScene {
    std::string mainFile;  // relative path of the scene file among `files`
    std::vector<std::pair<std::string, std::string>> files;  // relative path, bytes
    std::vector<SettingOverride> overrides;
    std::string camera;    // glTF: the camera to render (empty: the first)
    bool lenient = false;  // pbrt: what photon cannot render left out (ImportOptions::lenient)

    // Every file under `folder` that `include` accepts (by its relative path; all when
    // empty), `mainFile` naming the scene file in it.
    static FarmScene fromFolder(const std::filesystem::path& folder, const std::string& mainFile,
                                std::vector<SettingOverride> overrides,
                                const std::function<bool(const std::filesystem::path&)>& include = {});
    // The scene as a worker reads it, once unpacked to `main`.
    SceneFile read(const std::filesystem::path& main) const;
    // Stored as the job's scene hash (farm_keys.h), and read back; load returns nullopt when
    // the job has none (deleted).
    void store(RedisClient& redis, const std::string& job) const;
    static std::optional<FarmScene> load(RedisClient& redis, const std::string& job);
    // Writes the files under `folder` (created); throws std::invalid_argument for a path
    // that is absolute or climbs out with "..". Returns the main file's path.
    std::filesystem::path unpack(const std::filesystem::path& folder) const;
};

}  // namespace photon::farm
