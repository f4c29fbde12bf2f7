// What the image routes serve, value by value: the PNG tone-mapped with the scene's exposure,
// the denoised and raw layers of a denoised job, non-square images the right way round, and
// If-None-Match with lists, weak tags and "*".
#include <photon/image_io.h>
#include <photon/render.h>
#include <fstream>
#include "server_fixture.h"

namespace photon::test {
namespace {

class ImagesTest : public ServerTest {
protected:
    // The finished job's image in `format`, asserting 200.
    std::string finishedImage(const json& scene, const std::string& format) {
        std::string id = submitOk(scene);
        EXPECT_EQ(waitForStatus(id, "completed")["status"], "completed");
        httplib::Result res = client().Get(("/api/v1/jobs/" + id + "/image?format=" + format).c_str());
        EXPECT_TRUE(res && res->status == 200);
        return res ? res->body : "";
    }
};

// Three channels of an EXR held in memory, by name.
Image exrChannels(const std::string& bytes, const std::array<std::string, 3>& channels) {
    std::filesystem::path file = std::filesystem::temp_directory_path() /
                                 ("photon-channels-" + std::to_string(::getpid()) + ".exr");
    {
        std::ofstream out(file, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
    }
    Image image = readImageChannels(file, channels);
    std::filesystem::remove(file);
    return image;
}

TEST_F(ImagesTest, ThePngIsTheRenderToneMappedWithTheScenesExposure) {
    startServer();
    json scene = smallScene(2, 2000, 16);
    scene["render"]["exposure"] = 1.5;
    Image served = decodeImage(finishedImage(scene, "png"), "png");
    std::vector<uint8_t> expected = toneMapToSrgb8(renderInProcess(scene), 1.5f);
    ASSERT_EQ(served.rgb.size(), expected.size());
    size_t brighter = 0;
    std::vector<uint8_t> unexposed = toneMapToSrgb8(renderInProcess(scene), 0.0f);
    for (size_t i = 0; i < expected.size(); ++i) {
        ASSERT_FLOAT_EQ(served.rgb[i], expected[i] / 255.0f) << "value " << i;
        brighter += expected[i] > unexposed[i];
    }
    EXPECT_GT(brighter, expected.size() / 2);  // the exposure did change the picture
}

TEST_F(ImagesTest, ADenoisedJobServesTheEnginesDenoisedImageWithItsRawLayer) {
    startServer();
    json scene = smallScene(2, 2000, 16);
    scene["render"]["denoise"] = true;
    std::string exr = finishedImage(scene, "exr");
    Renderer renderer(SceneFile::parseJson(scene.dump(), PHOTON_SOURCE_DIR));
    CancelToken cancel;
    ASSERT_EQ(renderer.run(cancel), RenderOutcome::Completed);
    LayeredImage expected = renderer.layers();
    EXPECT_TRUE(exrChannels(exr, {"R", "G", "B"}).rgb == expected.main.rgb);
    EXPECT_TRUE(exrChannels(exr, {"raw.R", "raw.G", "raw.B"}).rgb == renderer.rawSnapshot().rgb);
    EXPECT_FALSE(expected.main.rgb == renderer.rawSnapshot().rgb);  // the filter did something
}

TEST_F(ImagesTest, ANonSquareImageKeepsItsShapeAndItsSidesWhereTheSceneHasThem) {
    startServer();
    json scene = smallScene(2, 20000, 16);
    scene["camera"]["resolution"] = {48, 24};
    Image served = decodeImage(finishedImage(scene, "exr"), "exr");
    Image local = renderInProcess(scene);
    ASSERT_EQ(served.width, 48);
    ASSERT_EQ(served.height, 24);
    EXPECT_TRUE(served.rgb == local.rgb);
    // The Cornell box: red wall on the left, green on the right, the light in the ceiling.
    auto columnMean = [&](int x0, int x1) {
        Color sum{0.0f};
        for (int y = 0; y < served.height; ++y)
            for (int x = x0; x < x1; ++x) sum += served.at(x, y);
        return sum;
    };
    Color left = columnMean(0, served.width / 2), right = columnMean(served.width / 2, served.width);
    // The light is orange, so every half is redder than green; the red wall makes the left
    // half redder than the right.
    EXPECT_GT(left.x / left.y, 1.2f * right.x / right.y) << "red wall on the left, green on the right";
    int brightestRow = 0;
    float brightest = 0;
    for (int y = 0; y < served.height; ++y)
        for (int x = 0; x < served.width; ++x)
            if (luminance(served.at(x, y)) > brightest) brightest = luminance(served.at(x, y)), brightestRow = y;
    EXPECT_LT(brightestRow, served.height / 4) << "the light at the top";
}

TEST_F(ImagesTest, IfNoneMatchTakesListsWeakTagsAndStar) {
    startServer();
    std::string id = submitOk(smallScene(2, 2000, 16));
    waitForStatus(id, "completed");
    const std::string path = "/api/v1/jobs/" + id + "/image?format=png";
    httplib::Client c = client();
    const std::string etag = c.Get(path.c_str())->get_header_value("ETag");
    ASSERT_EQ(etag, "\"" + id + "-2-png\"");
    auto statusWith = [&](const std::string& header) { return c.Get(path.c_str(), {{"If-None-Match", header}})->status; };
    EXPECT_EQ(statusWith(etag), 304);
    EXPECT_EQ(statusWith("\"other\", " + etag), 304);
    EXPECT_EQ(statusWith("\"other\",W/" + etag + " , \"more\""), 304);
    EXPECT_EQ(statusWith("W/" + etag), 304);
    EXPECT_EQ(statusWith("*"), 304);
    EXPECT_EQ(statusWith("\"other\", \"" + id + "-1-png\""), 200);
    EXPECT_EQ(statusWith("\"" + id + "-2-exr\""), 200);  // another format is another entity
    EXPECT_EQ(statusWith(""), 200);
}

}  // namespace
}  // namespace photon::test
