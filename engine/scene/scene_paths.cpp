#include "scene/scene_paths.h"
#include <algorithm>
#include <cctype>
#include <system_error>

namespace photon {

namespace fs = std::filesystem;

std::optional<std::string> checkRelativePath(const std::string& relative) {
    const char* outside = "must be a relative path inside the scene folder";
    if (relative.empty()) return outside;
    fs::path p(relative);
    // has_root_path also catches "/x" and, on Windows, "C:x" and "\\server\x".
    if (p.is_absolute() || p.has_root_path()) return outside;
    for (const fs::path& part : p)
        if (part == "..") return outside;
    return std::nullopt;
}

bool isInsideFolder(const fs::path& file, const fs::path& folder) {
    std::error_code ec;
    fs::path f = fs::weakly_canonical(fs::absolute(file, ec), ec);
    if (ec) return false;
    fs::path root = fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder, ec), ec);
    if (ec) return false;
    fs::path rel = f.lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}

std::string lowerCaseExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

}  // namespace photon
