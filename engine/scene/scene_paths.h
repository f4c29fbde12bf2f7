// Keeping the files a scene names inside the scene's folder: a scene may come from an
// untrusted upload, and must not read /etc/passwd through "../../" or a symlink.
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace photon {

// Why `relative` (as written in a scene) is not acceptable as a path inside the scene
// folder: absolute, empty, or with a ".." component. nullopt if it is fine.
std::optional<std::string> checkRelativePath(const std::string& relative);

// True if `file`, with symlinks resolved as far as it exists, lies inside `folder`.
bool isInsideFolder(const std::filesystem::path& file, const std::filesystem::path& folder);

// The file name's extension in lower case, with its dot (".png"), by which file kinds are told.
std::string lowerCaseExtension(const std::filesystem::path& file);

}  // namespace photon
