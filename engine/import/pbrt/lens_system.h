// pbrt-v4's RealisticCamera lens files: rows of LensInterface (description/lens_interface.h).
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "description/lens_interface.h"

namespace photon::pbrt {

// Rows of four numbers, '#' starting a comment (pbrt-v4 reads them with ReadFloatFile).
// Returns the interfaces, or a message saying what is wrong.
struct LensFile {
    std::vector<LensInterface> interfaces;
    std::string error;  // empty when read
};
LensFile parseLensFile(const std::string& text);

}  // namespace photon::pbrt
