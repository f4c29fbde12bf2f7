// An image's exact binary form, for snapshots that travel between processes (a render farm
// worker's image of a job it renders whole): every float as it was, zlib-compressed.
// Unlike EXR through OpenImageIO, it needs no file and keeps nothing but the pixels.
#pragma once
#include <string>
#include <string_view>
#include <photon/image.h>

namespace photon {

std::string encodeImageBytes(const Image& image);
// Throws std::invalid_argument, naming what is wrong, on anything encodeImageBytes did not
// write.
Image decodeImageBytes(std::string_view bytes);

}  // namespace photon
