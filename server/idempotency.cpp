#include "idempotency.h"
#include <chrono>
#include <cstdio>

namespace photon::server {

namespace {

constexpr uint64_t kFnvPrime = 1099511628211ull;

}  // namespace

std::optional<std::string> idempotencyKeyProblem(const std::string& key) {
    if (key.empty() || key.size() > kMaxIdempotencyKeyLength)
        return "Idempotency-Key: must be 1 to 255 characters, got " + std::to_string(key.size());
    for (char c : key)
        if (c < 0x20 || c > 0x7e) return std::string("Idempotency-Key: must be printable ASCII characters");
    return std::nullopt;
}

void RequestDigest::add(const char* data, size_t size) {
    for (size_t i = 0; i < size; ++i) {
        hash_ ^= static_cast<unsigned char>(data[i]);
        hash_ *= kFnvPrime;
    }
    fieldBytes_ += size;
}

void RequestDigest::endField() {
    // The field's length closes it: eight bytes, little-endian.
    for (int i = 0; i < 8; ++i) {
        hash_ ^= (fieldBytes_ >> (8 * i)) & 0xff;
        hash_ *= kFnvPrime;
    }
    fieldBytes_ = 0;
}

std::string RequestDigest::hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
    return text;
}

KeyLocks::Guard::Guard(KeyLocks& locks, std::string key) : locks_(locks), key_(std::move(key)) {
    std::unique_lock lock(locks_.mutex_);
    locks_.released_.wait(lock, [&] { return locks_.held_.count(key_) == 0; });
    locks_.held_.insert(key_);
}

KeyLocks::Guard::~Guard() {
    {
        std::lock_guard lock(locks_.mutex_);
        locks_.held_.erase(key_);
    }
    locks_.released_.notify_all();
}

int64_t unixNowSeconds() {
    return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

}  // namespace photon::server
