// Idempotent submission: a client that retries POST /api/v1/jobs with the same
// Idempotency-Key gets the job its first attempt created instead of a second one. A key
// maps to the job and a digest of the request (body and query), so reusing a key for a
// different request is detected; keys are kept for 24 hours, in the job database.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <set>
#include <string>

namespace photon::server {

constexpr int64_t kIdempotencyKeySeconds = 24 * 3600;
constexpr size_t kMaxIdempotencyKeyLength = 255;

// Why `key` is not a valid Idempotency-Key (1-255 printable ASCII characters); nullopt if it is.
std::optional<std::string> idempotencyKeyProblem(const std::string& key);

// 64-bit FNV-1a over length-framed fields: tells two requests apart, stable across builds
// and restarts (it is stored). Not a cryptographic hash: it guards against mistakes, and a
// client can only confuse itself with a crafted collision.
class RequestDigest {
public:
    void add(const char* data, size_t size);
    // A field boundary, so ("ab", "c") and ("a", "bc") differ.
    void endField();
    std::string hex() const;

private:
    uint64_t hash_ = 14695981039346656037ull;
    uint64_t fieldBytes_ = 0;
};

// Serialises requests that carry the same key: the second waits until the first has
// either stored its job (and then replays it) or failed.
class KeyLocks {
public:
    class Guard {
    public:
        Guard(KeyLocks& locks, std::string key);
        ~Guard();
        Guard(const Guard&) = delete;
        Guard& operator=(const Guard&) = delete;

    private:
        KeyLocks& locks_;
        std::string key_;
    };

private:
    std::mutex mutex_;
    std::condition_variable released_;
    std::set<std::string> held_;
};

// Seconds since the Unix epoch, for key expiry.
int64_t unixNowSeconds();

}  // namespace photon::server
