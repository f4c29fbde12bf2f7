// A connection to Redis (hiredis underneath): commands as argument lists, binary-safe, and
// their replies as plain values. One connection per thread; nothing here is shared.
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace photon::farm {

// Where Redis listens, from a redis://HOST:PORT address (the port defaults to 6379).
struct RedisAddress {
    std::string host;
    int port = 6379;
    // Throws std::invalid_argument naming what is wrong with the address.
    static RedisAddress parse(std::string_view url);
    std::string url() const { return "redis://" + host + ":" + std::to_string(port); }
};

// A connection that failed, or an error reply (the text Redis sent).
class RedisError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RedisReply {
    enum class Kind { Nil, Integer, String, Status, Array };
    Kind kind = Kind::Nil;
    long long integer = 0;
    std::string string;  // String and Status
    std::vector<RedisReply> elements;

    bool nil() const { return kind == Kind::Nil; }
    // The element at i of an array reply; throws RedisError on any other shape.
    const RedisReply& at(size_t i) const;
};

class RedisClient {
public:
    // Connects, waiting at most `timeout`; replies are awaited up to `readTimeout` (keep it
    // above the longest BLOCK a command asks for).
    RedisClient(const RedisAddress& address, std::chrono::milliseconds timeout = std::chrono::seconds(5),
                std::chrono::milliseconds readTimeout = std::chrono::seconds(30));
    ~RedisClient();
    RedisClient(RedisClient&&) noexcept;
    RedisClient& operator=(RedisClient&&) noexcept;

    // Sends the command and waits for its reply; throws RedisError if the connection fails
    // or Redis answers with an error. After a failed connection the next command connects
    // again.
    RedisReply command(const std::vector<std::string>& args);
    RedisReply command(std::initializer_list<std::string_view> args);

private:
    struct Connection;
    std::unique_ptr<Connection> connection_;
};

}  // namespace photon::farm
