// The image cache on its own: each pass encoded once, a running job's encodings at most
// every kMinEncodeInterval, the latest pass on demand.
#include <gtest/gtest.h>
#include "server/image_cache.h"

namespace photon::server {
namespace {

std::shared_ptr<const PendingImage> imageOf(float value) {
    Image image(8, 8);
    for (float& v : image.rgb) v = value;
    return std::make_shared<const PendingImage>(std::move(image), nullptr, 0.0f);
}

TEST(ImageCache, NewPassesAreEncodedAtMostEveryIntervalUnlessTheLatestIsAsked) {
    // The cache's clock stands still unless the test moves it.
    std::chrono::steady_clock::time_point now{};
    ImageCache cache([&] { return now; });
    EXPECT_FALSE(cache.get("job", ImageFormat::Png));
    cache.store("job", 1, imageOf(0.1f));
    EncodedImage first = *cache.get("job", ImageFormat::Png);
    EXPECT_EQ(first.pass, 1);
    // The same pass again: the very same bytes, not a new encoding.
    EXPECT_EQ(cache.get("job", ImageFormat::Png)->bytes, first.bytes);

    cache.store("job", 2, imageOf(0.5f));
    now += kMinEncodeInterval - std::chrono::milliseconds(1);
    EncodedImage soon = *cache.get("job", ImageFormat::Png);
    EXPECT_EQ(soon.pass, 1);  // too soon after pass 1's encoding
    EXPECT_EQ(soon.bytes, first.bytes);
    EncodedImage latest = *cache.get("job", ImageFormat::Png, Freshness::LatestPass);
    EXPECT_EQ(latest.pass, 2);
    EXPECT_NE(*latest.bytes, *first.bytes);
    EXPECT_EQ(cache.latestPass("job"), 2);

    cache.store("job", 3, imageOf(0.9f));
    now += kMinEncodeInterval - std::chrono::milliseconds(1);
    EXPECT_EQ(cache.get("job", ImageFormat::Png)->pass, 2);  // pass 2 was encoded just now
    now += std::chrono::milliseconds(1);
    EXPECT_EQ(cache.get("job", ImageFormat::Png)->pass, 3);  // the interval has passed
    // Formats are encoded apart: the EXR of pass 3 was never throttled by the PNG's.
    EXPECT_EQ(cache.get("job", ImageFormat::Exr)->pass, 3);
    cache.drop("job");
    EXPECT_FALSE(cache.get("job", ImageFormat::Png));
}

}  // namespace
}  // namespace photon::server
