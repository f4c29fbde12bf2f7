#include <photon/image_io.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace photon {

namespace {

// The sRGB transfer curve (IEC 61966-2-1) sampled at 2^16 linear steps: images are tone
// mapped every pass for live previews, and a table lookup is far cheaper than powf. The
// steps are fine enough that every one of the 256 output codes is reached.
class SrgbTable {
public:
    static constexpr int kSteps = 65535;
    SrgbTable() {
        for (int i = 0; i <= kSteps; ++i) {
            double v = static_cast<double>(i) / kSteps;
            v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
            table_[i] = static_cast<uint8_t>(std::lround(v * 255.0));
        }
    }
    uint8_t encode(float linear) const {
        float v = std::clamp(linear, 0.0f, 1.0f);  // NaN becomes 0 through the comparison below
        int index = v >= 0.0f ? static_cast<int>(v * kSteps + 0.5f) : 0;
        return table_[index];
    }

private:
    std::array<uint8_t, kSteps + 1> table_;
};

const SrgbTable& srgbTable() {
    static const SrgbTable table;
    return table;
}

// One writer for files and memory: `proxy` is null for files. writePixels writes the
// pixels into the opened output, false on failure.
void writeImage(const std::string& name, const OIIO::ImageSpec& spec, OIIO::Filesystem::IOProxy* proxy,
                const std::function<bool(OIIO::ImageOutput&)>& writePixels) {
    auto out = OIIO::ImageOutput::create(name);
    if (!out) throw std::runtime_error("cannot write " + name + ": " + OIIO::geterror());
    if (proxy) out->set_ioproxy(proxy);
    if (!out->open(name, spec) || !writePixels(*out) || !out->close())
        throw std::runtime_error("cannot write " + name + ": " + out->geterror());
}

void writeImage(const std::string& name, const OIIO::ImageSpec& spec, const void* pixels,
                OIIO::Filesystem::IOProxy* proxy) {
    writeImage(name, spec, proxy, [&](OIIO::ImageOutput& out) { return out.write_image(spec.format, pixels); });
}

// String attributes: PNG keeps only strings, as tEXt chunks (OpenImageIO's PNG writer drops
// other types), so every value is text in both formats.
void addMetadata(OIIO::ImageSpec& spec, const ImageMetadata& metadata) {
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
}

OIIO::ImageSpec exrSpec(const LayeredImage& image) {
    const int channels = 3 * static_cast<int>(1 + image.layers.size());
    OIIO::ImageSpec spec(image.main.width, image.main.height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B"};
    for (const ImageLayer& layer : image.layers)
        for (const std::string& c : layer.channels) spec.channelnames.push_back(layer.name + "." + c);
    spec.attribute("compression", "zip");
    return spec;
}

// The main image's and every layer's channels interleaved per pixel, written 64 rows at a
// time (a multiple of the 16 rows OpenEXR compresses together with zip): the interleaved
// copy of a whole 3840 x 2160 frame with its error layer took 190 MiB (docs/sppm.md#memory).
void writeExrStrips(const std::string& name, const LayeredImage& image, const ImageMetadata& metadata,
                    OIIO::Filesystem::IOProxy* proxy) {
    const int width = image.main.width, height = image.main.height;
    for (const ImageLayer& layer : image.layers)
        if (layer.image.width != width || layer.image.height != height)
            throw std::invalid_argument("EXR layer " + layer.name + " has another size");
    OIIO::ImageSpec spec = exrSpec(image);
    addMetadata(spec, metadata);
    constexpr int kStripRows = 64;
    const size_t channels = 3 * (1 + image.layers.size());
    std::vector<float> strip(static_cast<size_t>(width) * std::min(kStripRows, height) * channels);
    writeImage(name, spec, proxy, [&](OIIO::ImageOutput& out) {
        for (int y0 = 0; y0 < height; y0 += kStripRows) {
            const int y1 = std::min(height, y0 + kStripRows);
            const size_t first = static_cast<size_t>(y0) * width, pixels = static_cast<size_t>(y1 - y0) * width;
            for (size_t l = 0; l <= image.layers.size(); ++l) {
                const std::vector<float>& source = l == 0 ? image.main.rgb : image.layers[l - 1].image.rgb;
                for (size_t p = 0; p < pixels; ++p)
                    for (size_t c = 0; c < 3; ++c) strip[p * channels + 3 * l + c] = source[3 * (first + p) + c];
            }
            if (!out.write_scanlines(y0, y1, 0, OIIO::TypeDesc::FLOAT, strip.data())) return false;
        }
        return true;
    });
}

}  // namespace

std::vector<uint8_t> toneMapToSrgb8(const Image& image, float exposure) {
    float scale = std::exp2(exposure);
    const SrgbTable& table = srgbTable();
    std::vector<uint8_t> out(image.rgb.size());
    for (size_t i = 0; i < image.rgb.size(); ++i) out[i] = table.encode(image.rgb[i] * scale);
    return out;
}

void writeExr(const Image& image, const std::filesystem::path& file) {
    writeImage(file.string(), exrSpec({image, {}}), image.rgb.data(), nullptr);
}

void writeExr(const LayeredImage& image, const std::filesystem::path& file) {
    writeExrStrips(file.string(), image, {}, nullptr);
}

void writePng(const Image& image, const std::filesystem::path& file, float exposure) {
    std::vector<uint8_t> pixels = toneMapToSrgb8(image, exposure);
    writeImage(file.string(), OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::UINT8), pixels.data(),
               nullptr);
}

std::vector<uint8_t> encodePng(const Image& image, float exposure, const ImageMetadata& metadata) {
    std::vector<uint8_t> pixels = toneMapToSrgb8(image, exposure);
    std::vector<unsigned char> buffer;
    OIIO::Filesystem::IOVecOutput proxy(buffer);
    // Served images are encoded while the render runs: zlib's fastest level costs a third of
    // the default's time for files about 10% larger, and the Sub row filter alone a quarter
    // less than libpng's trying every filter on every row, for 2% more bytes (512x512
    // Cornell box: 12.8 vs 17.0 ms).
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("png:compressionLevel", 1);
    spec.attribute("png:filter", 0x10);  // PNG_FILTER_SUB
    addMetadata(spec, metadata);
    writeImage("image.png", spec, pixels.data(), &proxy);
    return {buffer.begin(), buffer.end()};
}

std::vector<uint8_t> encodeExr(const Image& image) { return encodeExr(LayeredImage{image, {}}); }

std::vector<uint8_t> encodeExr(const LayeredImage& image, const ImageMetadata& metadata) {
    std::vector<unsigned char> buffer;
    OIIO::Filesystem::IOVecOutput proxy(buffer);
    writeExrStrips("image.exr", image, metadata, &proxy);
    return {buffer.begin(), buffer.end()};
}

Image readImage(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw std::runtime_error("cannot read " + file.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> all(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read " + file.string() + ": " + in->geterror());
    Image image(spec.width, spec.height);
    for (size_t p = 0; p < static_cast<size_t>(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return image;
}

}  // namespace photon

namespace photon {

Image readImageChannels(const std::filesystem::path& file, const std::array<std::string, 3>& channels) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw std::runtime_error("cannot read " + file.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height);
    std::vector<float> plane(static_cast<size_t>(spec.width) * spec.height);
    for (int c = 0; c < 3; ++c) {
        int index = spec.channelindex(channels[c]);
        if (index < 0) throw std::runtime_error(file.string() + " has no channel " + channels[c]);
        if (!in->read_image(0, 0, index, index + 1, OIIO::TypeDesc::FLOAT, plane.data()))
            throw std::runtime_error("cannot read " + file.string() + ": " + in->geterror());
        for (size_t p = 0; p < plane.size(); ++p) image.rgb[3 * p + c] = plane[p];
    }
    return image;
}

}  // namespace photon
