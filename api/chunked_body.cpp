#include "api/chunked_body.h"
#include <algorithm>
#include <charconv>

namespace photon::api {

void ChunkedBodyScanner::fail(const std::string& message) {
    state_ = State::Failed;
    error_ = Refusal{400, "malformed chunked body: " + message};
}

bool ChunkedBodyScanner::lineEnded(char c) {
    line_ += c;
    if (line_.size() > maxLine_) {
        fail("a chunk-size or trailer line is longer than " + std::to_string(maxLine_) + " bytes");
        return false;
    }
    if (c != '\n') return false;
    if (line_.size() < 2 || line_[line_.size() - 2] != '\r') {
        fail("a line does not end in CRLF");
        return false;
    }
    line_.resize(line_.size() - 2);
    return true;
}

size_t ChunkedBodyScanner::consume(std::string_view bytes, std::string& forward) {
    size_t i = 0;
    while (i < bytes.size() && state_ != State::Done && state_ != State::Failed) {
        if (state_ == State::Data) {
            size_t take = size_t(std::min<uint64_t>(remaining_, bytes.size() - i));
            forward.append(bytes.substr(i, take));
            i += take;
            remaining_ -= take;
            if (remaining_ == 0) state_ = State::DataEnd;
            continue;
        }
        char c = bytes[i++];
        if (!lineEnded(c)) continue;
        if (state_ == State::SizeLine) {
            // chunk-size [; extensions]: the size is hexadecimal digits.
            std::string_view size(line_);
            size = size.substr(0, size.find(';'));
            while (!size.empty() && (size.back() == ' ' || size.back() == '\t')) size.remove_suffix(1);
            auto [end, ec] = std::from_chars(size.data(), size.data() + size.size(), remaining_, 16);
            if (size.empty() || ec != std::errc() || end != size.data() + size.size()) {
                fail("bad chunk size \"" + line_.substr(0, 32) + "\"");
                break;
            }
            char hex[24];
            auto written = std::to_chars(hex, hex + sizeof hex, remaining_, 16).ptr;
            forward.append(hex, written).append("\r\n");
            state_ = remaining_ == 0 ? State::Trailer : State::Data;
        } else if (state_ == State::DataEnd) {
            if (!line_.empty()) {
                fail("a chunk's data is longer than its size");
                break;
            }
            forward += "\r\n";
            state_ = State::SizeLine;
        } else if (state_ == State::Trailer) {
            if (line_.empty()) {
                forward += "\r\n";
                state_ = State::Done;
            }
            else if (++trailerFields_ > kMaxTrailerFields) {
                fail("more than " + std::to_string(kMaxTrailerFields) + " trailer fields");
                break;
            }
        }
        line_.clear();
    }
    return i;
}

}  // namespace photon::api
