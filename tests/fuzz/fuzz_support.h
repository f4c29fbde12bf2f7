// Shared by the fuzz targets: a scratch folder per process, removed at exit.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace photon::fuzz {

// A fresh folder under $TMPDIR (or /tmp); libFuzzer runs one input at a time, so a target
// can reuse the same files for every input.
inline std::filesystem::path scratchDir(const std::string& name) {
    std::string pattern = (std::filesystem::temp_directory_path() / (name + "-XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    static std::filesystem::path made;  // the last one; enough for one per process
    made = pattern;
    std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(made, ec);
    });
    return pattern;
}

}  // namespace photon::fuzz
