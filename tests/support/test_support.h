// Helpers shared by the engine tests.
#pragma once
#include <filesystem>
#include <string>

namespace photon::test {

// Absolute path of a file in the source tree, e.g. sourcePath("scenes/cornell-box.json").
inline std::filesystem::path sourcePath(const std::string& relative) {
    return std::filesystem::path(PHOTON_SOURCE_DIR) / relative;
}

}  // namespace photon::test
