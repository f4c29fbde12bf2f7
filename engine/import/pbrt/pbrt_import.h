// pbrt-v4 scene files (https://pbrt.org/fileformat-v4) as photon scenes: docs/import.md
// lists what maps onto what, what is approximated and what is refused.
#pragma once
#include <filesystem>
#include "description/imported_scene.h"

namespace photon {

// Reads `file` and what it includes. Throws SceneError at "file:line" for what photon
// cannot render as the file means it (participating media, unknown materials, ...).
ImportedScene importPbrt(const std::filesystem::path& file);

}  // namespace photon
