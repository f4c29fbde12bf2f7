#include <photon/texture_probe.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include "texture/image_texture.h"

namespace photon {

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
                if (comma > j) out.insert(std::string(".").append(exts, j, comma - j));
                j = comma + 1;
            }
            i = end + 1;
        }
        return out;
    }();
    return extensions;
}

}  // namespace

bool isImageFileName(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return imageExtensions().count(ext) != 0;
}

std::optional<ImageFileSize> probeImageFile(const std::filesystem::path& file) {
    if (!isImageFileName(file) || findPngChunkDamage(file)) return std::nullopt;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string());
    if (!in) {
        OIIO::geterror();  // clear it: the scene loader reports unreadable textures it uses
        return std::nullopt;
    }
    return ImageFileSize{in->spec().width, in->spec().height};
}

}  // namespace photon
