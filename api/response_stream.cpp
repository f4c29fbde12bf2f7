#include "api/response_stream.h"
#include <algorithm>
#include <charconv>
#include "api/request_head.h"

namespace photon::api {

namespace {

// httplib's heads are a few hundred bytes; anything near this is not one of them.
constexpr size_t kMaxResponseHead = 64 << 10;

}  // namespace

void ResponseStream::responseEnded() {
    if (!pending_.empty()) {
        if (pending_.front().endsConnection) closes_ = true;
        pending_.pop_front();
    }
    state_ = State::Head;
}

bool ResponseStream::headEnded() {
    // "HTTP/1.1 200 OK"
    std::string_view text(head_);
    if (text.size() < 12 || text.substr(0, 7) != "HTTP/1." || text[8] != ' ') return false;
    int status = 0;
    if (std::from_chars(text.data() + 9, text.data() + 12, status).ec != std::errc()) return false;
    bool chunked = false, hasLength = false, close = false;
    uint64_t length = 0;
    for (size_t pos = text.find("\r\n") + 2; pos < text.size();) {
        size_t end = text.find("\r\n", pos);
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 2;
        size_t colon = line.find(':');
        if (colon == std::string_view::npos) continue;
        std::string_view name = line.substr(0, colon), value = trimmed(line.substr(colon + 1));
        if (equalsIgnoringCase(name, "Content-Length")) {
            hasLength = std::from_chars(value.data(), value.data() + value.size(), length).ec == std::errc();
        } else if (equalsIgnoringCase(name, "Transfer-Encoding")) {
            chunked = equalsIgnoringCase(value, "chunked");
        } else if (equalsIgnoringCase(name, "Connection")) {
            close = close || equalsIgnoringCase(value, "close");
        }
    }
    head_.clear();
    if (status >= 100 && status < 200) return true;  // interim (100 Continue): the final one follows
    if (close) closes_ = true;
    bool bodiless = (!pending_.empty() && pending_.front().head) || status == 204 || status == 304;
    if (bodiless || (hasLength && length == 0 && !chunked)) {
        responseEnded();
    } else if (chunked) {
        state_ = State::Chunked;
        chunks_ = ChunkedBodyScanner(kMaxResponseHead);
    } else if (hasLength) {
        state_ = State::Length;
        left_ = length;
    } else {
        state_ = State::UntilClose;
        closes_ = true;
    }
    return true;
}

bool ResponseStream::consume(std::string_view bytes) {
    while (!bytes.empty()) {
        switch (state_) {
            case State::Head: {
                size_t before = head_.size();
                head_.append(bytes.substr(0, kMaxResponseHead));
                size_t end = head_.find("\r\n\r\n", before >= 3 ? before - 3 : 0);
                if (end == std::string::npos) {
                    if (head_.size() >= kMaxResponseHead) return false;
                    return true;
                }
                size_t taken = end + 4 - before;
                head_.resize(end + 2);
                bytes.remove_prefix(taken);
                if (!headEnded()) return false;
                break;
            }
            case State::Length: {
                size_t take = size_t(std::min<uint64_t>(left_, bytes.size()));
                bytes.remove_prefix(take);
                left_ -= take;
                if (left_ == 0) responseEnded();
                break;
            }
            case State::Chunked: {
                scratch_.clear();
                bytes.remove_prefix(chunks_.consume(bytes, scratch_));
                if (chunks_.error()) return false;
                if (chunks_.done()) responseEnded();
                break;
            }
            case State::UntilClose: return true;
        }
    }
    return true;
}

void ResponseStream::serverClosed() {
    if (state_ == State::UntilClose) responseEnded();
}

}  // namespace photon::api
