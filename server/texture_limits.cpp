#include "texture_limits.h"
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include "service_limits.h"
#include "texture/texture.h"

namespace photon::server {

namespace fs = std::filesystem;

namespace {

// OpenImageIO's "extension_list" is "format:ext,ext;format:ext;..."; lower-case extensions.
const std::set<std::string>& imageExtensions() {
    static const std::set<std::string> extensions = [] {
        std::set<std::string> out;
        std::string list = OIIO::get_string_attribute("extension_list");
        size_t i = 0;
        while (i < list.size()) {
            size_t end = list.find(';', i);
            if (end == std::string::npos) end = list.size();
            std::string entry = list.substr(i, end - i);
            size_t colon = entry.find(':');
            std::string exts = colon == std::string::npos ? "" : entry.substr(colon + 1);
            size_t j = 0;
            while (j <= exts.size()) {
                size_t comma = std::min(exts.find(',', j), exts.size());
                if (comma > j) out.insert("." + exts.substr(j, comma - j));
                j = comma + 1;
            }
            i = end + 1;
        }
        return out;
    }();
    return extensions;
}

bool isImageName(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return imageExtensions().count(ext) != 0;
}

}  // namespace

void checkTextureSizes(const fs::path& folder, int64_t maxPixels) {
    std::error_code ec;
    // Symlinks are not followed (and cannot be uploaded); only regular files count.
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec) || !isImageName(it->path())) continue;
        // Not even the header of a damaged PNG is read (see findPngChunkDamage); the scene
        // loader reports it if the scene uses it.
        if (findPngChunkDamage(it->path())) continue;
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(it->path().string());
        if (!in) {
            OIIO::geterror();  // clear it: the scene loader reports unreadable textures it uses
            continue;
        }
        const OIIO::ImageSpec& spec = in->spec();
        std::string name = it->path().lexically_relative(folder).generic_string();
        checkLimit(ErrorKind::LimitExceeded,
                   "texture " + name + " (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                       ") width*height",
                   int64_t(spec.width) * spec.height, maxPixels, "--max-texture-pixels");
    }
}

}  // namespace photon::server
