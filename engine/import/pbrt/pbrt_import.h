// pbrt-v4 scene files (https://pbrt.org/fileformat-v4) as photon scenes: docs/import.md
// lists what maps onto what, what is approximated and what is refused.
#pragma once
#include <filesystem>
#include "description/imported_scene.h"

namespace photon {

// Reads `file` and what it includes. Throws SceneError at "file:line" for what photon
// cannot render as the file means it (media that scatter, unknown materials, ...).
// lenient: what photon cannot render is left out or replaced with a warning, not refused.
ImportedScene importPbrt(const std::filesystem::path& file, bool lenient = false);

}  // namespace photon
