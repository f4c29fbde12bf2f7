// Image output: the sRGB tone curve at known points, exposure, lossless round trips
// through PNG and EXR with OpenImageIO (layers and metadata too), and resizing.
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <photon/image_io.h>
#include <photon/image_resize.h>

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

TEST(ImageIo, InMemoryEncodingsDecodeWithTheirLayersAndMetadata) {
    LayeredImage image{Image(5, 3), {}};
    Image raw(5, 3), normal(5, 3);
    for (size_t i = 0; i < image.main.rgb.size(); ++i) {
        image.main.rgb[i] = 0.25f * float(i);
        raw.rgb[i] = 100.0f + float(i);
        normal.rgb[i] = -1.0f + 0.01f * float(i);
    }
    image.layers = {{"raw", {"R", "G", "B"}, raw}, {"normal", {"X", "Y", "Z"}, normal}};
    const ImageMetadata metadata{{"Software", "photon test"}, {"photon:seed", "42"}};
    std::vector<uint8_t> exr = encodeExr(image, metadata);
    DecodedImage decoded = decodeImageBytes({reinterpret_cast<const char*>(exr.data()), exr.size()}, "exr");
    EXPECT_TRUE(decoded.image.main.rgb == image.main.rgb);
    // OpenEXR keeps layers sorted by name.
    ASSERT_EQ(decoded.image.layers.size(), 2u);
    EXPECT_EQ(decoded.image.layers[0].name, "normal");
    EXPECT_EQ(decoded.image.layers[0].channels, (std::array<std::string, 3>{"X", "Y", "Z"}));
    EXPECT_TRUE(decoded.image.layers[0].image.rgb == normal.rgb);
    EXPECT_EQ(decoded.image.layers[1].name, "raw");
    EXPECT_EQ(decoded.image.layers[1].channels, (std::array<std::string, 3>{"R", "G", "B"}));
    EXPECT_TRUE(decoded.image.layers[1].image.rgb == raw.rgb);
    auto value = [](const ImageMetadata& m, const std::string& key) {
        for (const auto& [k, v] : m)
            if (k == key) return v;
        return std::string("(missing)");
    };
    EXPECT_EQ(value(decoded.metadata, "Software"), "photon test");
    EXPECT_EQ(value(decoded.metadata, "photon:seed"), "42");
    std::vector<uint8_t> png = encodePng(image.main, 0, metadata);
    decoded = decodeImageBytes({reinterpret_cast<const char*>(png.data()), png.size()}, "png");
    EXPECT_EQ(decoded.image.main.width, 5);
    EXPECT_EQ(value(decoded.metadata, "photon:seed"), "42");
    EXPECT_THROW(decodeImageBytes("not an image", "exr"), std::runtime_error);
}

TEST(ImageIo, FitWithinKeepsTheAspectRatioAndNeverEnlarges) {
    EXPECT_EQ(fitWithin({48, 24}, {16, 16}), (ImageSize{16, 8}));
    EXPECT_EQ(fitWithin({48, 24}, {100, 6}), (ImageSize{12, 6}));
    EXPECT_EQ(fitWithin({48, 24}, {20, 5}), (ImageSize{10, 5}));
    EXPECT_EQ(fitWithin({640, 360}, {256, 256}), (ImageSize{256, 144}));
    EXPECT_EQ(fitWithin({1000, 3}, {10, 10}), (ImageSize{10, 1}));  // at least one pixel
    EXPECT_EQ(fitWithin({48, 24}, {48, 24}), (ImageSize{48, 24}));
    EXPECT_EQ(fitWithin({48, 24}, {4000, 30}), (ImageSize{48, 24}));
    EXPECT_EQ(fitWithin({48, 24}, {4000, 12}), (ImageSize{24, 12}));
}

TEST(ImageIo, ResizingKeepsAConstantImageAndABrightPointsEnergyAlsoAtTheEdges) {
    Image flat(37, 23);
    for (float& v : flat.rgb) v = 0.37f;
    Image small = resizeImage(flat, {10, 6});
    ASSERT_EQ(small.width, 10);
    ASSERT_EQ(small.height, 6);
    for (float v : small.rgb) ASSERT_NEAR(v, 0.37f, 1e-5f);  // the edges too

    // A light 10^4 times brighter than the floor: no negative ringing, and the light's
    // energy (value times pixel area) kept, wherever the light falls, on the border too.
    Image point(40, 40);
    for (int y : {0, 16, 17, 18, 19, 39})
        for (int x : {0, 1, 16, 17, 18, 19}) {
            for (float& v : point.rgb) v = 0.1f;
            point.set(x, y, Color(1000.0f));
            for (int side : {10, 13, 27}) {
                Image thumb = resizeImage(point, {side, side});
                double sum = 0;
                for (float v : thumb.rgb) {
                    ASSERT_GE(v, 0.0999f);
                    sum += v;
                }
                double expected = (0.1 * 40 * 40 * 3 + 999.9 * 3) * side * side / (40.0 * 40.0);
                EXPECT_NEAR(sum, expected, 0.005 * expected) << "light at " << x << "," << y << ", side " << side;
            }
        }
    EXPECT_THROW(resizeImage(point, {41, 10}), std::invalid_argument);
}

}  // namespace
}  // namespace photon
