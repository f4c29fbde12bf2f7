#include "texture_limits.h"
#include <photon/texture_probe.h>
#include <string>
#include "service_limits.h"

namespace photon::server {

namespace fs = std::filesystem;

void checkTextureSizes(const fs::path& folder, const Limits& limits) {
    std::error_code ec;
    // Symlinks are not followed (and cannot be uploaded); only regular files count.
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        std::optional<ImageFileSize> size = probeImageFile(it->path());
        if (!size) continue;  // not an image, or unreadable: the scene loader reports it if used
        std::string name = it->path().lexically_relative(folder).generic_string();
        checkLimit(ErrorKind::LimitExceeded,
                   "the pixel count of texture " + name + " (" + std::to_string(size->width) + " x " +
                       std::to_string(size->height) + ")",
                   int64_t(size->width) * size->height, limits, &Limits::maxTexturePixels);
    }
}

}  // namespace photon::server
