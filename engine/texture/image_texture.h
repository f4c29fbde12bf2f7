// An RGB (or single-channel) image texture held in memory, read through OpenImageIO.
#pragma once
#include <compare>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "texture/texture.h"

namespace photon {

// libpng believes a chunk's declared length and reserves that much memory before it finds
// the file shorter: a 2 KB file declaring a 2 GB chunk reserves 2 GB. So a PNG's chunk
// lengths are checked against the file before any decoder opens it. Returns what is wrong
// (with the chunk and its byte offset), or nothing for a sound PNG or a file of another kind.
std::optional<std::string> findPngChunkDamage(const std::filesystem::path& file);

// Which of an image's channels a texture reads.
enum class ImageChannels {
    Color,  // RGB (a grey image replicated); alpha ignored
    Alpha,  // the alpha channel in all three (cutouts); an image without one reads its grey/RGB mean
    Data,   // RGB as stored, integers scaled to [0, 1] without the sRGB curve (normal maps)
    // One channel in all three, as stored: data such as roughness or metallic packed into
    // one image (glTF's metallicRoughnessTexture keeps them linear, glTF 2.0 sec. 3.9.2),
    // never the sRGB curve. A grey image's grey serves for R, G and B; an image without
    // alpha reads A as 1 (opaque).
    R,
    G,
    B,
    A,
};

// How an integer image's values become linear (pbrt-v4's imagemap "encoding"). Float images
// (EXR, HDR, PFM) are linear whatever it says, and alpha is always read as stored.
struct ImageEncoding {
    enum Kind : uint8_t {
        Default,  // colour through the sRGB curve; a single channel as stored (glTF's data)
        Srgb,     // through the sRGB curve, a single channel too (pbrt-v4's float imagemap)
        Gamma,    // as stored to the power `gamma`
    };
    Kind kind = Default;
    float gamma = 0;
    auto operator<=>(const ImageEncoding&) const = default;
};

// What an image reads outside its unit square of uv (pbrt-v4's imagemap "wrap"): its
// repeats, its edge texels stretched outward, or black. The bilinear filter follows the
// same rule at the edges.
enum class ImageWrap : uint8_t { Repeat, Clamp, Black };

class ImageTexture final : public Texture {
public:
    // Reads any format OpenImageIO knows. 8-bit and other integer images are taken as
    // sRGB-encoded and linearised (alpha is linear in every format); float images (EXR,
    // HDR) as linear; `encoding` says otherwise for integer images. With `bytes`, the
    // file's contents are those bytes, held in memory (`file` then only names it, its
    // extension the format). Throws std::runtime_error with the reason on failure.
    static std::shared_ptr<const ImageTexture> load(const std::filesystem::path& file,
                                                    ImageChannels channels = ImageChannels::Color,
                                                    const std::string* bytes = nullptr,
                                                    ImageEncoding encoding = {});
    ImageTexture(int width, int height, std::vector<Color> texels);

    // Bilinear lookup with wrap-around addressing; v = 0 is the bottom row (OBJ convention).
    Color lookup(const TexturePoint& at) const override { return lookup(at.uv, ImageWrap::Repeat); }
    Color lookup(Vec2 uv, ImageWrap wrap) const;
    Color average() const override { return average_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // Texel (x, y), row 0 at the top of the image.
    Color texel(int x, int y) const { return texels_[size_t(y) * width_ + x]; }

private:
    int width_, height_;
    std::vector<Color> texels_;
    Color average_;
};

}  // namespace photon
