// The latest pass image of each running job, and its encodings. A pass stores one snapshot;
// the first request for a format encodes it, later requests for the same pass reuse the
// bytes. So encoding costs at most one PNG and one EXR per pass, however many clients poll.
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <photon/image_io.h>
#include <photon/pending_image.h>
#include "image_format.h"

namespace photon::server {

struct EncodedImage {
    int pass = 0;
    std::shared_ptr<const std::string> bytes;
    std::chrono::steady_clock::time_point encodedAt;
};

// Which pass a request gets: the newest, or, while a newer pass's encoding is less than
// kMinEncodeInterval away from the last one, the last encoded (fast renders finish ten
// passes a second, and encoding each costs a PNG ~15 ms of CPU the render would lose).
enum class Freshness { Throttled, LatestPass };
inline constexpr std::chrono::milliseconds kMinEncodeInterval{250};

class ImageCache {
public:
    using Clock = std::function<std::chrono::steady_clock::time_point()>;
    // `now` tells the time for the encoding interval (tests set the clock by hand).
    explicit ImageCache(Clock now = std::chrono::steady_clock::now) : now_(std::move(now)) {}

    // The image after `pass` as the engine hands it out (its layers go into the EXR, the
    // PNG shows the main image; a post filter runs at the first encode, so only for passes
    // someone fetches), with the text its encodings carry; replaces the previous pass's
    // image and encodings.
    void store(const std::string& id, int pass, std::shared_ptr<const PendingImage> image,
               ImageMetadata metadata = {});
    // The latest image in `format`, encoded now if this pass has not been encoded yet.
    // nullopt if the job has no image in memory.
    std::optional<EncodedImage> get(const std::string& id, ImageFormat format,
                                    Freshness freshness = Freshness::Throttled);
    std::optional<int> latestPass(const std::string& id) const;
    void drop(const std::string& id);

private:
    struct Slot {
        // Encoding runs under encodeMutex only, so the render thread storing the next pass
        // (under stateMutex) never waits for an encode.
        std::mutex encodeMutex;  // concurrent requests for one pass wait for a single encode
        std::mutex stateMutex;
        int pass = 0;
        std::shared_ptr<const PendingImage> image;
        std::shared_ptr<const ImageMetadata> metadata;  // shared with encodes in flight
        std::map<ImageFormat, EncodedImage> encoded;
    };
    std::shared_ptr<Slot> slot(const std::string& id) const;

    Clock now_;
    mutable std::mutex mutex_;  // guards the map only, never held while encoding
    std::unordered_map<std::string, std::shared_ptr<Slot>> slots_;
};

}  // namespace photon::server
