#include "image_cache.h"
#include <photon/image_io.h>

namespace photon::server {

namespace {

std::shared_ptr<const std::string> encode(const PendingImage& image, const ImageMetadata& metadata,
                                          ImageFormat format) {
    std::vector<uint8_t> bytes = format == ImageFormat::Png ? encodePng(image, metadata) : encodeExr(image, metadata);
    return std::make_shared<const std::string>(bytes.begin(), bytes.end());
}

}  // namespace

std::shared_ptr<ImageCache::Slot> ImageCache::slot(const std::string& id) const {
    std::lock_guard lock(mutex_);
    auto it = slots_.find(id);
    return it == slots_.end() ? nullptr : it->second;
}

void ImageCache::store(const std::string& id, int pass, std::shared_ptr<const PendingImage> image,
                       ImageMetadata metadata) {
    std::shared_ptr<Slot> s;
    {
        std::lock_guard lock(mutex_);
        auto& entry = slots_[id];
        if (!entry) entry = std::make_shared<Slot>();
        s = entry;
    }
    std::lock_guard lock(s->stateMutex);
    s->pass = pass;
    s->image = std::move(image);
    s->metadata = std::make_shared<const ImageMetadata>(std::move(metadata));
    // The last encodings stay: a request soon after may still be answered with them.
}

std::optional<EncodedImage> ImageCache::get(const std::string& id, ImageFormat format, Freshness freshness) {
    std::shared_ptr<Slot> s = slot(id);
    if (!s) return std::nullopt;
    std::lock_guard encoding(s->encodeMutex);
    std::shared_ptr<const PendingImage> image;
    std::shared_ptr<const ImageMetadata> metadata;
    EncodedImage fresh;
    {
        std::lock_guard state(s->stateMutex);
        if (!s->image) return std::nullopt;
        auto it = s->encoded.find(format);
        if (it != s->encoded.end()) {
            const EncodedImage& last = it->second;
            bool recent = now_() - last.encodedAt < kMinEncodeInterval;
            if (last.pass == s->pass || (freshness == Freshness::Throttled && recent)) return last;
        }
        image = s->image;
        metadata = s->metadata;
        fresh.pass = s->pass;
    }
    fresh.bytes = encode(*image, *metadata, format);
    fresh.encodedAt = now_();
    std::lock_guard state(s->stateMutex);
    // Keyed by pass: if a newer pass arrived meanwhile, the lookup above will not match it.
    s->encoded[format] = fresh;
    return fresh;
}

std::optional<int> ImageCache::latestPass(const std::string& id) const {
    std::shared_ptr<Slot> s = slot(id);
    if (!s) return std::nullopt;
    std::lock_guard lock(s->stateMutex);
    if (!s->image) return std::nullopt;
    return s->pass;
}

void ImageCache::drop(const std::string& id) {
    std::lock_guard lock(mutex_);
    slots_.erase(id);
}

}  // namespace photon::server
