// What a service needs to know of an uploaded image before the engine decodes it: its size,
// from the file's header alone (no pixels are read), so a small compressed upload cannot
// make it allocate gigabytes of texels.
#pragma once
#include <filesystem>
#include <optional>

namespace photon {

struct ImageFileSize {
    int width = 0, height = 0;
};

// Whether the file name's extension is one the engine's texture reader knows.
bool isImageFileName(const std::filesystem::path& file);

// The size in the image file's header, or nothing when the file is not an image the
// texture reader knows, its header cannot be read, or it is a PNG with damaged chunk
// lengths (whose header is then not even opened): the scene loader reports such a file if
// the scene uses it.
std::optional<ImageFileSize> probeImageFile(const std::filesystem::path& file);

}  // namespace photon
