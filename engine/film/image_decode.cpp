// Encoded images read back from memory, with their layers and header text: what a service
// needs to make other encodings (exposures, sizes) of an image it holds only encoded.
#include <photon/image_io.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <optional>
#include <stdexcept>

namespace photon {

namespace {

// "normal.X" -> {"normal", "X"}; no dot: nothing.
std::optional<std::pair<std::string, std::string>> splitChannel(const std::string& name) {
    size_t dot = name.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == name.size()) return std::nullopt;
    return std::pair{name.substr(0, dot), name.substr(dot + 1)};
}

// Channels [first, first + 3) of interleaved pixels with `stride` channels each.
Image channelsOf(const std::vector<float>& pixels, int width, int height, int stride, int first) {
    Image image(width, height);
    const size_t count = static_cast<size_t>(width) * height;
    for (size_t p = 0; p < count; ++p)
        for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = pixels[p * stride + std::min(first + c, stride - 1)];
    return image;
}

}  // namespace

DecodedImage decodeImageBytes(std::string_view bytes, const std::string& extension) {
    const std::string name = "image." + extension;  // picks the reader
    OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open(name, nullptr, &proxy);
    if (!in) throw std::runtime_error("cannot read the " + extension + " image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int stride = spec.nchannels;
    std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * stride);
    if (!in->read_image(0, 0, 0, stride, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw std::runtime_error("cannot read the " + extension + " image: " + in->geterror());

    DecodedImage decoded;
    decoded.image.main = channelsOf(pixels, spec.width, spec.height, stride, 0);
    for (int c = 3; c + 2 < stride; ++c) {
        auto a = splitChannel(spec.channelnames[c]);
        auto b = splitChannel(spec.channelnames[c + 1]);
        auto d = splitChannel(spec.channelnames[c + 2]);
        if (!a || !b || !d || a->first != b->first || a->first != d->first) continue;
        decoded.image.layers.push_back(
            {a->first, {a->second, b->second, d->second}, channelsOf(pixels, spec.width, spec.height, stride, c)});
        c += 2;
    }
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.type() == OIIO::TypeDesc::STRING) decoded.metadata.emplace_back(p.name().string(), p.get_string());
    return decoded;
}

}  // namespace photon
