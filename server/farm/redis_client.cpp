// RedisClient over hiredis's blocking API (redisCommandArgv), whose argument lengths make
// every command binary-safe.
#include "redis_client.h"
#include <hiredis/hiredis.h>
#include <sys/time.h>
#include <charconv>

namespace photon::farm {
namespace {

timeval toTimeval(std::chrono::milliseconds ms) {
    return timeval{static_cast<time_t>(ms.count() / 1000), static_cast<suseconds_t>((ms.count() % 1000) * 1000)};
}

RedisReply convert(const redisReply* r) {
    RedisReply out;
    switch (r->type) {
        case REDIS_REPLY_INTEGER:
            out.kind = RedisReply::Kind::Integer;
            out.integer = r->integer;
            break;
        case REDIS_REPLY_STRING:
            out.kind = RedisReply::Kind::String;
            out.string.assign(r->str, r->len);
            break;
        case REDIS_REPLY_STATUS:
            out.kind = RedisReply::Kind::Status;
            out.string.assign(r->str, r->len);
            break;
        case REDIS_REPLY_ARRAY:
            out.kind = RedisReply::Kind::Array;
            for (size_t i = 0; i < r->elements; ++i) out.elements.push_back(convert(r->element[i]));
            break;
        default: break;  // nil
    }
    return out;
}

}  // namespace

RedisAddress RedisAddress::parse(std::string_view url) {
    constexpr std::string_view scheme = "redis://";
    if (url.substr(0, scheme.size()) != scheme)
        throw std::invalid_argument("a Redis address is redis://HOST:PORT, not \"" + std::string(url) + "\"");
    std::string_view rest = url.substr(scheme.size());
    if (!rest.empty() && rest.back() == '/') rest.remove_suffix(1);
    RedisAddress a;
    const size_t colon = rest.rfind(':');
    a.host = std::string(rest.substr(0, colon));
    if (colon != std::string_view::npos) {
        std::string_view port = rest.substr(colon + 1);
        int value = 0;
        auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
        if (ec != std::errc() || end != port.data() + port.size() || value < 1 || value > 65535)
            throw std::invalid_argument("the port of \"" + std::string(url) + "\" is not a number from 1 to 65535");
        a.port = value;
    }
    if (a.host.empty()) throw std::invalid_argument("\"" + std::string(url) + "\" names no host");
    return a;
}

const RedisReply& RedisReply::at(size_t i) const {
    if (kind != Kind::Array || i >= elements.size())
        throw RedisError("unexpected reply from Redis: no element " + std::to_string(i));
    return elements[i];
}

struct RedisClient::Connection {
    RedisAddress address;
    std::chrono::milliseconds timeout, readTimeout;
    redisContext* context = nullptr;

    // A new connection in place of the old, or RedisError.
    void open() {
        close();
        context = redisConnectWithTimeout(address.host.c_str(), address.port, toTimeval(timeout));
        if (!context) throw RedisError("cannot reach Redis at " + address.url());
        if (context->err) {
            const std::string why = context->errstr;
            close();
            throw RedisError("cannot reach Redis at " + address.url() + ": " + why);
        }
        redisSetTimeout(context, toTimeval(readTimeout));
    }
    void close() {
        if (context) redisFree(context);
        context = nullptr;
    }
    ~Connection() { close(); }
};

RedisClient::RedisClient(const RedisAddress& address, std::chrono::milliseconds timeout,
                         std::chrono::milliseconds readTimeout)
    : connection_(std::make_unique<Connection>()) {
    connection_->address = address;
    connection_->timeout = timeout;
    connection_->readTimeout = readTimeout;
    connection_->open();
}

RedisClient::~RedisClient() = default;
RedisClient::RedisClient(RedisClient&&) noexcept = default;
RedisClient& RedisClient::operator=(RedisClient&&) noexcept = default;

RedisReply RedisClient::command(const std::vector<std::string>& args) {
    std::vector<const char*> argv;
    std::vector<size_t> lengths;
    for (const std::string& a : args) argv.push_back(a.data()), lengths.push_back(a.size());
    // A connection that failed before (Redis restarted, the network dropped) is opened
    // again first; if that fails too, this command fails.
    if (!connection_->context || connection_->context->err) connection_->open();
    redisContext* c = connection_->context;
    auto* reply = static_cast<redisReply*>(redisCommandArgv(c, int(argv.size()), argv.data(), lengths.data()));
    if (!reply) throw RedisError(std::string("Redis connection failed: ") + c->errstr);
    std::unique_ptr<redisReply, void (*)(void*)> owned(reply, freeReplyObject);
    if (reply->type == REDIS_REPLY_ERROR) throw RedisError(std::string(reply->str, reply->len));
    return convert(reply);
}

RedisReply RedisClient::command(std::initializer_list<std::string_view> args) {
    return command(std::vector<std::string>(args.begin(), args.end()));
}

}  // namespace photon::farm
