// Holding uploaded images to the texture size limit before the engine decodes them: only
// each file's header is read (OpenImageIO's ImageInput::open reads the spec, no pixels), so a
// small compressed upload cannot make the server allocate gigabytes of texels.
#pragma once
#include <cstdint>
#include <filesystem>
#include "service_limits.h"

namespace photon::server {

// Checks every file under `folder` whose extension OpenImageIO reads. Throws ServiceError
// (LimitExceeded) naming the file, its size and --max-texture-pixels when width*height is
// over limits.maxTexturePixels. Files that are not readable images are left to the scene loader.
void checkTextureSizes(const std::filesystem::path& folder, const Limits& limits);

}  // namespace photon::server
