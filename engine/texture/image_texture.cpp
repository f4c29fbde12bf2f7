#include "texture/image_texture.h"
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <optional>
#include <stdexcept>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace photon {

namespace {

// Limits that keep a scene upload from exhausting memory: 64M texels is 768 MB as floats.
constexpr int kMaxTextureSide = 16384;
constexpr int64_t kMaxTexels = int64_t(64) << 20;

// The exact sRGB EOTF (IEC 61966-2-1), not the 2.2 power approximation.
float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// 8-bit images are by far the most common: one table lookup per channel.
const std::array<float, 256>& srgb8Table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgbToLinear(i / 255.0f);
        return t;
    }();
    return table;
}

void checkSize(const OIIO::ImageSpec& spec) {
    if (spec.width <= 0 || spec.height <= 0) throw std::runtime_error("image has no pixels");
    if (spec.depth > 1) throw std::runtime_error("volume images are not supported as textures");
    if (spec.deep) throw std::runtime_error("deep images are not supported as textures");
    if (spec.width > kMaxTextureSide || spec.height > kMaxTextureSide ||
        int64_t(spec.width) * spec.height > kMaxTexels)
        throw std::runtime_error("image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                 ", larger than the limit of " + std::to_string(kMaxTextureSide) + " pixels a side and " +
                                 std::to_string(kMaxTexels >> 20) + "M pixels in total");
}

// Reads channels [first, first + channels) (1: grey or alpha, 3: RGB) as `T`.
template <typename T>
std::vector<T> readPixels(OIIO::ImageInput& in, int first, int channels, OIIO::TypeDesc type) {
    const OIIO::ImageSpec& spec = in.spec();
    std::vector<T> data(size_t(spec.width) * spec.height * channels);
    if (!in.read_image(0, 0, first, first + channels, type, data.data())) {
        std::string err = in.geterror();
        throw std::runtime_error(err.empty() ? "cannot read image" : err);
    }
    return data;
}

// Grey images are replicated into all three channels.
template <typename T, typename Decode>
std::vector<Color> toColors(const std::vector<T>& data, int channels, Decode decode) {
    std::vector<Color> texels(data.size() / channels);
    for (size_t i = 0; i < texels.size(); ++i) {
        const T* p = &data[i * channels];
        texels[i] = channels == 1 ? Color(decode(p[0])) : Color(decode(p[0]), decode(p[1]), decode(p[2]));
    }
    return texels;
}

// With ImageChannels R, G, B or A, the image channel to read (-1: A of an image without
// alpha, which reads as opaque); nothing for the other kinds.
std::optional<int> selectedChannel(ImageChannels which, const OIIO::ImageSpec& spec) {
    if (which == ImageChannels::A) return spec.alpha_channel;
    const bool rgb = spec.nchannels >= 3;
    if (which == ImageChannels::R) return 0;
    if (which == ImageChannels::G) return rgb ? 1 : 0;
    if (which == ImageChannels::B) return rgb ? 2 : 0;
    return std::nullopt;
}

}  // namespace

namespace {

// The check on a stream of `size` bytes (a file, or an image held in memory).
std::optional<std::string> pngChunkDamage(std::istream& in, uint64_t size) {
    static constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
    char signature[8];
    if (!in.read(signature, 8) || std::memcmp(signature, kSignature, 8) != 0) return std::nullopt;
    // Each chunk (PNG spec, sec. 5.3): 4-byte big-endian length, 4-letter type, data, CRC.
    for (uint64_t at = 8; at + 12 <= size;) {
        unsigned char head[8];
        if (!in.seekg(static_cast<std::streamoff>(at)) || !in.read(reinterpret_cast<char*>(head), 8))
            return std::nullopt;
        uint32_t length = (uint32_t(head[0]) << 24) | (uint32_t(head[1]) << 16) | (uint32_t(head[2]) << 8) | head[3];
        std::string type(reinterpret_cast<const char*>(head + 4), 4);
        if (!std::all_of(type.begin(), type.end(), [](unsigned char c) { return std::isalpha(c); }))
            return "damaged PNG: no chunk type at byte " + std::to_string(at + 4);
        const uint64_t follow = size - at - 12;  // bytes after this chunk's header and CRC
        if (length > 0x7fffffffu || length > follow)
            return "damaged PNG: chunk " + type + " at byte " + std::to_string(at) + " declares " +
                   std::to_string(length) + " bytes of data, but the file has " + std::to_string(follow) +
                   " after it";
        if (type == "IEND") return std::nullopt;
        at += 12 + uint64_t(length);
    }
    return std::nullopt;  // cut short before IEND: OIIO reports that
}

}  // namespace

std::optional<std::string> findPngChunkDamage(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(file, ec);
    if (!in || ec) return std::nullopt;
    return pngChunkDamage(in, size);
}

std::shared_ptr<const ImageTexture> ImageTexture::load(const std::filesystem::path& file, ImageChannels which,
                                                       const std::string* bytes, ImageEncoding encoding) {
    std::optional<std::string> damage;
    if (bytes) {
        std::istringstream in(*bytes);
        damage = pngChunkDamage(in, bytes->size());
    } else {
        damage = findPngChunkDamage(file);
    }
    if (damage) throw std::runtime_error(*damage);
    // Keep colour as stored: by default OIIO premultiplies unassociated alpha (PNG), which
    // would darken texels wherever alpha < 1; alpha, where wanted, is read on its own.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    // An image in memory is read through OpenImageIO's I/O proxy, the name giving its format.
    std::optional<OIIO::Filesystem::IOMemReader> memory;
    if (bytes) {
        memory.emplace(const_cast<char*>(bytes->data()), bytes->size());
        void* proxy = &*memory;
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    }
    auto in = OIIO::ImageInput::open(file.string(), &config);
    if (!in) {
        std::string err = OIIO::geterror();
        throw std::runtime_error(err.empty() ? "cannot open image" : err);
    }
    const OIIO::ImageSpec& spec = in->spec();
    checkSize(spec);
    const bool alpha = which == ImageChannels::Alpha && spec.alpha_channel >= 0;
    const int first = alpha ? spec.alpha_channel : 0;
    const int channels = alpha ? 1 : (spec.nchannels >= 3 ? 3 : 1);

    std::vector<Color> texels;
    const bool decodes = !spec.format.is_floating_point() && encoding.kind != ImageEncoding::Default;
    if (auto channel = selectedChannel(which, spec)) {
        // A single channel is data, as stored, unless an encoding is given for it (pbrt-v4
        // reads a float imagemap's first channel through the texture's encoding).
        const bool decodesChannel = decodes && which != ImageChannels::A;
        texels = *channel < 0 ? std::vector<Color>(size_t(spec.width) * spec.height, Color(1.0f))
                              : toColors(readPixels<float>(*in, *channel, 1, OIIO::TypeDesc::FLOAT), 1, [&](float v) {
                                    if (!(std::isfinite(v) && v > 0)) return 0.0f;
                                    if (!decodesChannel) return v;
                                    v = std::min(v, 1.0f);
                                    return encoding.kind == ImageEncoding::Gamma ? std::pow(v, encoding.gamma)
                                                                                 : srgbToLinear(v);
                                });
    } else if (alpha) {
        // Coverage is stored linearly in every format.
        texels = toColors(readPixels<float>(*in, first, 1, OIIO::TypeDesc::FLOAT), 1,
                          [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f; });
    } else if (which == ImageChannels::Data) {
        // Vectors, not colours: integer formats arrive normalised to [0, 1], undecoded.
        texels = toColors(readPixels<float>(*in, first, channels, OIIO::TypeDesc::FLOAT), channels,
                          [](float v) { return std::isfinite(v) ? v : 0.0f; });
    } else if (decodes && encoding.kind == ImageEncoding::Gamma) {
        // A power-law encoding (integer formats arrive normalised to [0, 1]).
        texels = toColors(readPixels<float>(*in, first, channels, OIIO::TypeDesc::FLOAT), channels,
                          [&](float v) { return std::pow(std::clamp(v, 0.0f, 1.0f), encoding.gamma); });
    } else if (spec.format == OIIO::TypeDesc::UINT8) {
        const auto& table = srgb8Table();
        texels = toColors(readPixels<uint8_t>(*in, first, channels, OIIO::TypeDesc::UINT8), channels,
                          [&](uint8_t v) { return table[v]; });
    } else if (spec.format.is_floating_point()) {
        // Float images (EXR, HDR) hold linear values; NaN, inf and negative texels would
        // break the energy bookkeeping of photon tracing, so they become 0.
        texels = toColors(readPixels<float>(*in, first, channels, OIIO::TypeDesc::FLOAT), channels,
                          [](float v) { return std::isfinite(v) && v > 0 ? v : 0.0f; });
    } else {
        // Other integer formats (16-bit PNG, TIFF) arrive normalised to [0, 1], still sRGB.
        texels = toColors(readPixels<float>(*in, first, channels, OIIO::TypeDesc::FLOAT), channels,
                          [](float v) { return srgbToLinear(std::clamp(v, 0.0f, 1.0f)); });
    }
    if (which == ImageChannels::Alpha && !alpha)  // no alpha channel: the mean of what there is
        for (Color& c : texels) c = Color((c.x + c.y + c.z) / 3.0f);
    return std::make_shared<const ImageTexture>(spec.width, spec.height, std::move(texels));
}

ImageTexture::ImageTexture(int width, int height, std::vector<Color> texels)
    : width_(width), height_(height), texels_(std::move(texels)) {
    if (width <= 0 || height <= 0 || texels_.size() != size_t(width) * size_t(height))
        throw std::invalid_argument("ImageTexture: texel count does not match width x height");
    // Bilinear filtering with wrap-around preserves the mean, so this is exactly the
    // average of lookup() over the unit square. Summed in double: 64M floats would lose
    // precision in a float accumulator.
    double sum[3] = {0, 0, 0};
    for (const Color& c : texels_)
        for (int k = 0; k < 3; ++k) sum[k] += c[k];
    double n = double(texels_.size());
    average_ = Color(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
}

Color ImageTexture::lookup(Vec2 uv, ImageWrap wrap) const {
    if (wrap == ImageWrap::Black && !(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1)) return Color(0.0f);
    const bool repeat = wrap == ImageWrap::Repeat;
    // Into [0, 1) first for a repeat, [0, 1] otherwise: this is the wrap, and it keeps the
    // float→int casts below defined for any uv. Non-finite uvs read as 0.
    auto reduce = [repeat](float t) {
        if (!std::isfinite(t)) return 0.0f;
        if (!repeat) return std::clamp(t, 0.0f, 1.0f);
        float f = t - std::floor(t);
        return f < 1.0f ? f : 0.0f;  // t = -1e-9 gives f = 1 after rounding
    };
    // Texel centres sit at (i + 0.5) / size. Image row 0 is the top, v = 0 the bottom.
    float fx = reduce(uv.x) * width_ - 0.5f;
    float fy = (1.0f - reduce(uv.y)) * height_ - 0.5f;
    float x0f = std::floor(fx), y0f = std::floor(fy);
    float tx = fx - x0f, ty = fy - y0f;
    // The filter's neighbour past an edge: across it for a repeat, the edge texel otherwise.
    auto index = [repeat](int i, int n) {
        if (!repeat) return std::clamp(i, 0, n - 1);
        return i < 0 ? i + n : (i >= n ? i - n : i);
    };
    int x0 = index(int(x0f), width_), x1 = index(int(x0f) + 1, width_);
    int y0 = index(int(y0f), height_), y1 = index(int(y0f) + 1, height_);
    Color top = texel(x0, y0) * (1 - tx) + texel(x1, y0) * tx;
    Color bottom = texel(x0, y1) * (1 - tx) + texel(x1, y1) * tx;
    return top * (1 - ty) + bottom * ty;
}

}  // namespace photon
