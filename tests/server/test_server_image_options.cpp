// The image route's options, value by value: ?exposure= tone-maps the PNG at that exposure
// (2^EV times the linear render), ?size= serves the engine's resampling of the render within
// the box, the files carry the render's metadata, each variant has its own ETag and file
// name, and bad values are 400 problems naming the parameter.
#include <photon/image_io.h>
#include <photon/image_resize.h>
#include <cmath>
#include "server_fixture.h"

namespace photon::test {
namespace {

using Query = std::string;

class ImageOptionsTest : public ServerTest {
protected:
    // A finished job of `scene` (its record).
    json finishedJob(const json& scene, const std::string& submitQuery = "") {
        std::string id = submitOk(scene, submitQuery);
        json job = waitForStatus(id, "completed");
        EXPECT_EQ(job["status"], "completed");
        return job;
    }
    httplib::Result getImage(const std::string& id, const Query& query, const httplib::Headers& headers = {}) {
        return client().Get(("/api/v1/jobs/" + id + "/image" + query).c_str(), headers);
    }
    // The body of a 200 answer, asserting the status.
    std::string body(const std::string& id, const Query& query) {
        httplib::Result res = getImage(id, query);
        EXPECT_TRUE(res && res->status == 200) << query << ": " << (res ? res->body : "no answer");
        return res ? res->body : "";
    }
};

json cornell(int width, int height) {
    json scene = smallScene(2, 4000, 16);
    scene["camera"]["resolution"] = {width, height};
    return scene;
}

// The linear value an 8-bit sRGB code stands for (IEC 61966-2-1).
double srgbToLinear(double code) {
    double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

Color meanOf(const Image& image) {
    Color sum{0.0f};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += image.at(x, y);
    return sum / float(image.width * image.height);
}

std::string metadataValue(const ImageMetadata& metadata, const std::string& key) {
    for (const auto& [k, v] : metadata)
        if (k == key) return v;
    return "(missing " + key + ")";
}

TEST_F(ImageOptionsTest, ExposureTonemapsThePngAtThatExposureInsteadOfTheScenes) {
    startServer();
    json scene = cornell(16, 16);
    scene["render"]["exposure"] = 1.5;
    std::string id = finishedJob(scene)["id"];
    Image local = renderInProcess(scene);
    for (auto [text, ev] : {std::pair{"1", 1.0f}, {"0", 0.0f}, {"-2.5", -2.5f}}) {
        Image served = decodeImage(body(id, std::string("?exposure=") + text), "png");
        std::vector<uint8_t> expected = toneMapToSrgb8(local, ev);
        ASSERT_EQ(served.rgb.size(), expected.size());
        for (size_t i = 0; i < expected.size(); ++i)
            ASSERT_FLOAT_EQ(served.rgb[i], expected[i] / 255.0f) << "exposure " << ev << ", value " << i;
    }
    // Undoing the sRGB curve, +1 EV is twice the light of 0 EV wherever neither is clipped
    // or lost in the lowest codes (8-bit steps there are coarse).
    Image one = decodeImage(body(id, "?exposure=1"), "png"), zero = decodeImage(body(id, "?exposure=0"), "png");
    double sumOne = 0, sumZero = 0;
    size_t counted = 0;
    for (size_t i = 0; i < one.rgb.size(); ++i) {
        double codeZero = std::round(zero.rgb[i] * 255), codeOne = std::round(one.rgb[i] * 255);
        if (codeZero < 40 || codeOne > 250) continue;
        sumOne += srgbToLinear(codeOne);
        sumZero += srgbToLinear(codeZero);
        ++counted;
    }
    ASSERT_GT(counted, one.rgb.size() / 4);
    EXPECT_NEAR(sumOne / sumZero, 2.0, 0.02);
}

TEST_F(ImageOptionsTest, AThumbnailIsTheEnginesResamplingOfTheRenderWithinTheBox) {
    startServer();
    json scene = cornell(48, 24);
    scene["render"]["denoise"] = true;  // layers too
    scene["render"]["exposure"] = 0;
    std::string id = finishedJob(scene)["id"];
    DecodedImage full = decodeImageBytes(body(id, "?format=exr"), "exr");
    ASSERT_EQ(full.image.main.width, 48);

    // The box's tighter side is met exactly, the other follows the aspect ratio (rounded).
    struct Case {
        std::string box;
        int width, height;
    };
    for (const Case& c : {Case{"16x16", 16, 8}, Case{"100x6", 12, 6}, Case{"47x24", 47, 24}, Case{"1x1", 1, 1},
                          Case{"3x1", 2, 1}}) {
        Image png = decodeImage(body(id, "?size=" + c.box), "png");
        EXPECT_EQ(png.width, c.width) << c.box;
        EXPECT_EQ(png.height, c.height) << c.box;
    }

    DecodedImage thumb = decodeImageBytes(body(id, "?format=exr&size=16x16"), "exr");
    ASSERT_EQ(thumb.image.main.width, 16);
    ASSERT_EQ(thumb.image.main.height, 8);
    // Exactly the engine's own resampling of the image, layers alike.
    LayeredImage expected = resizeImage(full.image, {16, 8});
    EXPECT_TRUE(thumb.image.main.rgb == expected.main.rgb);
    ASSERT_EQ(thumb.image.layers.size(), full.image.layers.size());
    for (size_t l = 0; l < thumb.image.layers.size(); ++l) {
        EXPECT_EQ(thumb.image.layers[l].name, full.image.layers[l].name);
        EXPECT_TRUE(thumb.image.layers[l].image.rgb == expected.layers[l].image.rgb) << thumb.image.layers[l].name;
    }
    // The filter (over the image mirrored at its edges) keeps the mean light, for the image
    // and the undenoised layer: within 0.1% (float rounding) where the ratio is whole.
    auto expectSameMean = [](const Image& small, const Image& large, const std::string& what) {
        Color a = meanOf(small), b = meanOf(large);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 0.001f * b[c]) << what << " channel " << c;
    };
    expectSameMean(thumb.image.main, full.image.main, "main");
    for (size_t l = 0; l < thumb.image.layers.size(); ++l)
        if (thumb.image.layers[l].name == "raw")
            expectSameMean(thumb.image.layers[l].image, full.image.layers[l].image, "raw");
    // No negative radiance (a filter with negative lobes rings around the light).
    for (float v : thumb.image.main.rgb) ASSERT_GE(v, 0.0f);

    // The PNG thumbnail is the resampled render tone-mapped with the scene's exposure.
    Image png = decodeImage(body(id, "?size=16x16"), "png");
    std::vector<uint8_t> tonemapped = toneMapToSrgb8(expected.main, 0.0f);
    for (size_t i = 0; i < tonemapped.size(); ++i) ASSERT_FLOAT_EQ(png.rgb[i], tonemapped[i] / 255.0f);
    // With an exposure too.
    Image brighter = decodeImage(body(id, "?size=16x16&exposure=2"), "png");
    tonemapped = toneMapToSrgb8(expected.main, 2.0f);
    for (size_t i = 0; i < tonemapped.size(); ++i) ASSERT_FLOAT_EQ(brighter.rgb[i], tonemapped[i] / 255.0f);

    // A box the render fits in is the plain image: never enlarged, the same bytes.
    EXPECT_EQ(body(id, "?format=exr&size=48x24"), body(id, "?format=exr"));
    EXPECT_EQ(body(id, "?size=4000x30"), body(id, ""));
}

TEST_F(ImageOptionsTest, TheFilesCarryTheRendersMetadata) {
    startServer();
    json scene = cornell(16, 16);
    scene["render"]["exposure"] = 0.75;
    json job = finishedJob(scene, "?seed=4242&passes=3");
    std::string id = job["id"];
    ASSERT_EQ(job["pass"], 3);
    auto expectJobMetadata = [&](const ImageMetadata& m, const std::string& exposure, const std::string& what) {
        EXPECT_EQ(metadataValue(m, "Software"), std::string("photon ") + PHOTON_VERSION_FOR_TESTS) << what;
        EXPECT_EQ(metadataValue(m, "photon:integrator"), job["settings"]["integrator"].get<std::string>()) << what;
        EXPECT_EQ(metadataValue(m, "photon:integrator"), "sppm") << what;
        EXPECT_EQ(metadataValue(m, "photon:passes"), "3") << what;
        EXPECT_EQ(metadataValue(m, "photon:photons_traced"), std::to_string(job["photons_traced"].get<int64_t>()))
            << what;
        EXPECT_EQ(metadataValue(m, "photon:photons_traced"), "12000") << what;
        EXPECT_EQ(metadataValue(m, "photon:seed"), "4242") << what;
        // The very number the job record holds, to the last bit.
        EXPECT_EQ(std::stod(metadataValue(m, "photon:elapsed_seconds")), job["elapsed_seconds"].get<double>()) << what;
        EXPECT_GT(job["elapsed_seconds"].get<double>(), 0.0);
        EXPECT_EQ(metadataValue(m, "photon:exposure"), exposure) << what;
    };
    // The PNG's tone-mapping exposure, the EXR's the scene's.
    expectJobMetadata(decodeImageBytes(body(id, "?format=png"), "png").metadata, "0.75", "png");
    expectJobMetadata(decodeImageBytes(body(id, "?format=exr"), "exr").metadata, "0.75", "exr");
    expectJobMetadata(decodeImageBytes(body(id, "?exposure=-1.25"), "png").metadata, "-1.25", "png at -1.25 EV");
    expectJobMetadata(decodeImageBytes(body(id, "?size=8x8"), "png").metadata, "0.75", "png thumbnail");
    expectJobMetadata(decodeImageBytes(body(id, "?format=exr&size=8x8"), "exr").metadata, "0.75", "exr thumbnail");
    // In the PNG as tEXt chunks (uncompressed Latin-1 text any viewer shows).
    const std::string png = body(id, "");
    EXPECT_NE(png.find(std::string("tEXtSoftware\0photon ", 20)), std::string::npos);
    EXPECT_NE(png.find(std::string("tEXtphoton:seed\0" "4242", 20)), std::string::npos);
}

TEST_F(ImageOptionsTest, ARunningJobsImageSaysWhichPassItShows) {
    startServer();
    std::string id = submitOk(longScene(), "?seed=99");
    waitFor(id, [](const json& j) { return j["pass"].get<int>() >= 2; });
    for (const Query& query : {Query("?format=png"), Query("?format=exr&size=12x12"), Query("?exposure=3")}) {
        httplib::Result res = getImage(id, query);
        ASSERT_TRUE(res && res->status == 200) << query;
        int pass = std::stoi(res->get_header_value("X-Photon-Pass"));
        ImageMetadata m = decodeImageBytes(res->body, query.find("exr") != std::string::npos ? "exr" : "png").metadata;
        EXPECT_EQ(metadataValue(m, "photon:passes"), std::to_string(pass)) << query;
        EXPECT_EQ(metadataValue(m, "photon:photons_traced"), std::to_string(int64_t(pass) * 20000)) << query;
        EXPECT_EQ(metadataValue(m, "photon:seed"), "99") << query;
    }
}

TEST_F(ImageOptionsTest, EachVariantHasItsOwnNameAndEtagAndRevalidates) {
    startServer();
    std::string id = finishedJob(cornell(48, 24))["id"];
    const std::string tag = "\"" + id + "-2-";
    const std::string file = "inline; filename=\"" + id + "-pass2";
    struct Case {
        Query query;
        std::string etag, disposition;
    };
    const std::vector<Case> cases{
        {"", tag + "png\"", file + ".png\""},
        {"?format=exr", tag + "exr\"", file + ".exr\""},
        {"?exposure=1.5", tag + "png-ev1.5\"", file + "-ev1.5.png\""},
        {"?size=16x16", tag + "png-16x8\"", file + "-16x8.png\""},
        {"?format=exr&size=16x16", tag + "exr-16x8\"", file + "-16x8.exr\""},
        {"?format=exr&size=20x5", tag + "exr-10x5\"", file + "-10x5.exr\""},
        {"?size=16x16&exposure=-2", tag + "png-16x8-ev-2\"", file + "-16x8-ev-2.png\""},
    };
    for (const Case& c : cases) {
        httplib::Result res = getImage(id, c.query);
        ASSERT_TRUE(res && res->status == 200) << c.query;
        EXPECT_EQ(res->get_header_value("ETag"), c.etag) << c.query;
        EXPECT_EQ(res->get_header_value("Content-Disposition"), c.disposition) << c.query;
        EXPECT_EQ(res->get_header_value("X-Photon-Pass"), "2") << c.query;
        // Its own tag revalidates; every other variant's is another entity.
        EXPECT_EQ(getImage(id, c.query, {{"If-None-Match", c.etag}})->status, 304) << c.query;
        for (const Case& other : cases)
            if (other.etag != c.etag)
                EXPECT_EQ(getImage(id, c.query, {{"If-None-Match", other.etag}})->status, 200)
                    << c.query << " with " << other.etag;
    }
    // One exposure written in other ways is one entity; a box the image fits in is the plain one.
    EXPECT_EQ(getImage(id, "?exposure=1.50")->get_header_value("ETag"), tag + "png-ev1.5\"");
    EXPECT_EQ(getImage(id, "?exposure=15e-1")->get_header_value("ETag"), tag + "png-ev1.5\"");
    EXPECT_EQ(getImage(id, "?exposure=-0")->get_header_value("ETag"), tag + "png-ev0\"");
    EXPECT_EQ(getImage(id, "?size=48x24")->get_header_value("ETag"), tag + "png\"");
    EXPECT_EQ(getImage(id, "?format=exr&size=500x500")->get_header_value("Content-Disposition"), file + ".exr\"");
}

TEST_F(ImageOptionsTest, BadValuesAreProblemsNamingTheParameter) {
    startServer();
    std::string id = finishedJob(cornell(16, 16))["id"];
    const std::string exposureRange = "query parameter exposure: expected a number in [-20, 20]";
    const std::string sizeForm = "query parameter size: expected WIDTHxHEIGHT, each a whole number in [1, 65536]";
    const std::vector<std::pair<Query, std::string>> cases{
        {"?format=exr&exposure=1", "query parameter exposure: applies to format=png only (the EXR is linear)"},
        {"?format=exr&exposure=0&size=8x8", "query parameter exposure: applies to format=png only (the EXR is linear)"},
        {"?exposure=", exposureRange},
        {"?exposure=abc", exposureRange},
        {"?exposure=1ev", exposureRange},
        {"?exposure=nan", exposureRange},
        {"?exposure=inf", exposureRange},
        {"?exposure=-inf", exposureRange},
        {"?exposure=1e999", exposureRange},
        {"?exposure=20.5", exposureRange},
        {"?exposure=-21", exposureRange},
        {"?exposure=%201", exposureRange},  // "+1" would reach the server as " 1"
        {"?exposure=1&exposure=2", "query parameter exposure given more than once"},
        {"?size=", sizeForm},
        {"?size=16", sizeForm},
        {"?size=16x", sizeForm},
        {"?size=x16", sizeForm},
        {"?size=0x16", sizeForm},
        {"?size=16x0", sizeForm},
        {"?size=-4x16", sizeForm},
        {"?size=16x16x16", sizeForm},
        {"?size=16X16", sizeForm},
        {"?size=16%20x16", sizeForm},
        {"?size=65537x16", sizeForm},
        {"?size=16x99999999999999999999", sizeForm},
        {"?format=gif&size=8x8", "query parameter format: expected png or exr"},
    };
    for (const auto& [query, detail] : cases) {
        httplib::Result res = getImage(id, query);
        ASSERT_TRUE(res) << query;
        EXPECT_EQ(res->status, 400) << query;
        json problem = problemOf(res);
        EXPECT_EQ(problem["detail"], detail) << query;
        EXPECT_EQ(problem["type"], "urn:photon:problem:bad-request") << query;
    }
    // The edges of the ranges are fine.
    for (const Query& query : {Query("?exposure=20"), Query("?exposure=-20"), Query("?size=65536x1")})
        EXPECT_EQ(getImage(id, query)->status, 200) << query;
    // An unknown job is still a 404, whatever the options.
    EXPECT_EQ(getImage("0123456789abcdef", "?size=8x8")->status, 404);
    EXPECT_EQ(getImage("0123456789abcdef", "?exposure=1")->status, 404);
}

// The first pass at or after each power of two is kept: 1, 2, 4, 8 of 9, each served as
// the image that pass was (the same pixels as a job of that many passes), in any format and
// variant; the list and the images survive a restart.
TEST_F(ImageOptionsTest, EarlierPassesAreKeptAtPowersOfTwo) {
    startServer();
    json nine = smallScene(9, 4000, 16);
    json four = smallScene(4, 4000, 16);
    const std::string id = finishedJob(nine)["id"];
    const std::string other = finishedJob(four)["id"];
    json job = json::parse(client().Get(("/api/v1/jobs/" + id).c_str())->body);
    EXPECT_EQ(job["kept_passes"], json::parse("[1, 2, 4, 8]"));
    const Image kept = decodeImage(body(id, "?pass=4&format=exr"), ".exr");
    EXPECT_EQ(kept.rgb, decodeImage(body(other, "?format=exr"), ".exr").rgb);
    EXPECT_NE(kept.rgb, decodeImage(body(id, "?format=exr"), ".exr").rgb);
    httplib::Result png = getImage(id, "?pass=2&size=8x8");
    ASSERT_EQ(png->status, 200);
    EXPECT_EQ(png->get_header_value("X-Photon-Pass"), "2");
    EXPECT_EQ(png->get_header_value("ETag"), "\"" + id + "-2-png-8x8\"");
    EXPECT_EQ(decodeImage(png->body, ".png").width, 8);

    // The latest pass by its number is the latest image.
    EXPECT_EQ(body(id, "?pass=9&format=exr"), body(id, "?format=exr"));
    httplib::Result missing = getImage(id, "?pass=3");
    EXPECT_EQ(missing->status, 404);
    EXPECT_EQ(problemOf(missing)["title"], "Not found");
    EXPECT_EQ(problemOf(missing)["detail"], "job " + id +
                                                " kept no image of pass 3 (it keeps the first pass at or after each "
                                                "power of two; kept: 1, 2, 4, 8)");
    httplib::Result zero = getImage(id, "?pass=0");
    EXPECT_EQ(zero->status, 400);
    EXPECT_EQ(problemOf(zero)["detail"], "query parameter pass: expected a whole number >= 1");

    // The progress history: a point a pass, photons adding up.
    json history = json::parse(client().Get(("/api/v1/jobs/" + id + "/progress").c_str())->body);
    ASSERT_EQ(history["points"].size(), 9u) << history.dump();
    for (int i = 0; i < 9; ++i) {
        EXPECT_EQ(history["points"][i]["pass"], i + 1);
        EXPECT_EQ(history["points"][i]["photons_traced"], 4000 * (i + 1));
        EXPECT_GT(history["points"][i]["mean_radius"].get<double>(), 0);
    }
    EXPECT_EQ(client().Get("/api/v1/jobs/0123456789abcdef/progress")->status, 404);

    ASSERT_EQ(stopServer(), 0);
    startServer({"--workers", "0"});
    job = json::parse(client().Get(("/api/v1/jobs/" + id).c_str())->body);
    EXPECT_EQ(job["kept_passes"], json::parse("[1, 2, 4, 8]"));
    EXPECT_EQ(decodeImage(body(id, "?pass=4&format=exr"), ".exr").rgb, kept.rgb);
    EXPECT_EQ(json::parse(client().Get(("/api/v1/jobs/" + id + "/progress").c_str())->body), history);
}

// ?layer=raw serves a denoised job's image before the filter, in either format, and is
// refused for a job without the denoiser.
TEST_F(ImageOptionsTest, TheRawLayerOfADenoisedJob) {
    startServer();
    json scene = smallScene(2, 4000, 16);
    scene["render"]["denoise"] = true;
    const json job = finishedJob(scene);
    const std::string id = job["id"];
    EXPECT_EQ(job["settings"]["denoise"], true);
    const DecodedImage plain = decodeImageBytes(body(id, "?format=exr"), "exr");
    const auto rawLayer = std::find_if(plain.image.layers.begin(), plain.image.layers.end(),
                                       [](const ImageLayer& l) { return l.name == "raw"; });
    ASSERT_NE(rawLayer, plain.image.layers.end());
    const Image raw = decodeImage(body(id, "?format=exr&layer=raw"), ".exr");
    EXPECT_EQ(raw.rgb, rawLayer->image.rgb);
    EXPECT_NE(raw.rgb, plain.image.main.rgb);
    httplib::Result png = getImage(id, "?layer=raw");
    EXPECT_EQ(png->get_header_value("ETag"), "\"" + id + "-2-png-raw\"");
    EXPECT_NE(png->body, body(id, ""));  // the plain PNG shows the filtered image

    const json plainJob = finishedJob(smallScene(2, 4000, 16));
    EXPECT_EQ(plainJob["settings"]["denoise"], false);
    httplib::Result refused = getImage(plainJob["id"], "?layer=raw");
    EXPECT_EQ(refused->status, 400);
    EXPECT_EQ(problemOf(refused)["detail"], "query parameter layer: job " + plainJob["id"].get<std::string>() +
                                                " is not denoised, so its image is the raw one");
    EXPECT_EQ(getImage(id, "?layer=albedo")->status, 400);
}

}  // namespace
}  // namespace photon::test
