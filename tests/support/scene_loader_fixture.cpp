#include "scene_loader_fixture.h"
#include <OpenImageIO/imageio.h>

namespace photon::test {

namespace {
template <typename T> constexpr OIIO::TypeDesc::BASETYPE kSampleType = OIIO::TypeDesc::UNKNOWN;
template <> constexpr OIIO::TypeDesc::BASETYPE kSampleType<uint8_t> = OIIO::TypeDesc::UINT8;
template <> constexpr OIIO::TypeDesc::BASETYPE kSampleType<uint16_t> = OIIO::TypeDesc::UINT16;
template <> constexpr OIIO::TypeDesc::BASETYPE kSampleType<float> = OIIO::TypeDesc::FLOAT;
}  // namespace

template <typename T>
void writeImage(const fs::path& p, int w, int h, int channels, const std::vector<T>& pixels) {
    const OIIO::TypeDesc type(kSampleType<T>);
    fs::create_directories(p.parent_path());
    auto out = OIIO::ImageOutput::create(p.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(w, h, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // write colour as given, even where alpha is 0
    ASSERT_TRUE(out->open(p.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
    out->close();
}

template void writeImage<uint8_t>(const fs::path&, int, int, int, const std::vector<uint8_t>&);
template void writeImage<uint16_t>(const fs::path&, int, int, int, const std::vector<uint16_t>&);
template void writeImage<float>(const fs::path&, int, int, int, const std::vector<float>&);

}  // namespace photon::test
