// Finds where a chunked request body ends (RFC 9112 section 7.1) as its bytes arrive, so the
// connection guard forwards exactly that body and reads the next request's head after it.
// Chunk-size lines and trailer fields are bounded like a head; the data is not buffered.
//
// What is forwarded is the body re-framed from what was parsed: each chunk's size in plain
// hexadecimal, without extensions, and no trailer fields (a recipient may drop them, RFC 9110
// section 6.5.1; httplib refuses a body that has any).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include "api/refusal.h"

namespace photon::api {

class ChunkedBodyScanner {
public:
    explicit ChunkedBodyScanner(size_t maxLineBytes = 64 << 10) : maxLine_(maxLineBytes) {}

    // How many of `bytes` belong to the body (all of them unless it ends inside them); the body
    // to forward for them is appended to `forward`.
    size_t consume(std::string_view bytes, std::string& forward);
    bool done() const { return state_ == State::Done; }
    // Set when the body is malformed; nothing more is consumed.
    const std::optional<Refusal>& error() const { return error_; }

private:
    enum class State { SizeLine, Data, DataEnd, Trailer, Done, Failed };
    bool lineEnded(char c);  // appends c to line_; true at its CRLF
    void fail(const std::string& message);

    static constexpr int kMaxTrailerFields = 100;  // as many as a head may have

    size_t maxLine_;
    int trailerFields_ = 0;
    State state_ = State::SizeLine;
    uint64_t remaining_ = 0;
    std::string line_;
    std::optional<Refusal> error_;
};

}  // namespace photon::api
