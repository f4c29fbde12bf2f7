// Image output: the sRGB tone curve at known points, exposure, and lossless round trips
// through PNG and EXR with OpenImageIO.
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <photon/image_io.h>

namespace photon {
namespace {

uint8_t toneMapOne(float linear, float exposure = 0) {
    Image image(1, 1);
    image.set(0, 0, Color(linear));
    return toneMapToSrgb8(image, exposure)[0];
}

TEST(ImageIo, SrgbCurveAtKnownPoints) {
    EXPECT_EQ(toneMapOne(0.0f), 0);
    EXPECT_EQ(toneMapOne(1.0f), 255);
    EXPECT_EQ(toneMapOne(4.0f), 255);   // clipped
    EXPECT_EQ(toneMapOne(-1.0f), 0);    // clipped
    EXPECT_EQ(toneMapOne(NAN), 0);      // never garbage
    EXPECT_EQ(toneMapOne(0.5f), 188);   // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
    EXPECT_EQ(toneMapOne(0.18f), 118);  // middle grey: 0.4614
    EXPECT_EQ(toneMapOne(0.002f), 7);   // linear segment: 12.92 * 0.002 = 0.02584
    EXPECT_EQ(toneMapOne(0.25f, 1.0f), toneMapOne(0.5f));  // +1 stop doubles
}

TEST(ImageIo, PngAndExrRoundTrips) {
    Image image(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) image.set(x, y, Color(0.1f * x, 0.2f * y, 3.5f + x * y));
    auto dir = std::filesystem::temp_directory_path() / ("photon-image-io-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    writeExr(image, dir / "a.exr");
    writePng(image, dir / "a.png", 0);
    Image exr = readImage(dir / "a.exr");
    EXPECT_EQ(exr.width, 7);
    EXPECT_EQ(exr.height, 5);
    EXPECT_TRUE(exr.rgb == image.rgb);  // float EXR is lossless
    Image png = readImage(dir / "a.png");
    std::vector<uint8_t> expected = toneMapToSrgb8(image, 0);
    ASSERT_EQ(png.rgb.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(png.rgb[i] * 255.0f, expected[i], 1e-3f);
    // The in-memory encodings are the same files.
    EXPECT_GT(encodePng(image, 0).size(), 8u);
    EXPECT_GT(encodeExr(image).size(), 8u);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace photon
