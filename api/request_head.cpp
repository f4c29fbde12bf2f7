#include "api/request_head.h"
#include <algorithm>
#include <cctype>
#include "api/guard_fields.h"

namespace photon::api {

namespace {

constexpr std::string_view kCrlf = "\r\n";

// RFC 9110 section 5.6.2: the characters of a token (field names, methods).
bool isTokenChar(unsigned char c) {
    return std::isalnum(c) || std::string_view("!#$%&'*+-.^_`|~").find(char(c)) != std::string_view::npos;
}

bool isToken(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return isTokenChar(c); });
}

HeadScan refused(int status, std::string message) {
    HeadScan scan;
    scan.state = HeadScan::State::Refused;
    scan.refusal = {status, std::move(message)};
    return scan;
}

// "GET /path HTTP/1.1": three parts separated by single spaces (RFC 9112 section 3).
bool parseRequestLine(std::string_view line, RequestHead& head) {
    size_t first = line.find(' ');
    size_t last = line.rfind(' ');
    if (first == std::string_view::npos || first == last) return false;
    head.method = line.substr(0, first);
    head.target = line.substr(first + 1, last - first - 1);
    head.version = line.substr(last + 1);
    bool targetOk = !head.target.empty() && std::none_of(head.target.begin(), head.target.end(), [](unsigned char c) {
        return c <= 0x20 || c == 0x7f;
    });
    return isToken(head.method) && targetOk && (head.version == "HTTP/1.1" || head.version == "HTTP/1.0");
}

}  // namespace

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](unsigned char x, unsigned char y) {
               return std::tolower(x) == std::tolower(y);
           });
}

std::vector<std::string> RequestHead::values(std::string_view name) const {
    std::vector<std::string> found;
    for (const auto& [n, v] : fields)
        if (equalsIgnoringCase(n, name)) found.push_back(v);
    return found;
}

HeadScan scanRequestHead(std::string_view buffered, const HeadLimits& limits) {
    size_t start = 0;
    while (buffered.substr(start, 2) == kCrlf) start += 2;
    std::string_view rest = buffered.substr(start);
    size_t end = rest.find("\r\n\r\n");
    size_t headBytes = end == std::string_view::npos ? rest.size() : end + 4;
    size_t lineEnd = rest.find(kCrlf);
    if (lineEnd == std::string_view::npos ? rest.size() > limits.maxBytes : lineEnd + 2 > limits.maxBytes)
        return refused(414, "the request line is longer than " + std::to_string(limits.maxBytes) + " bytes");
    if (headBytes > limits.maxBytes)
        return refused(431, "the request's header fields are longer than " + std::to_string(limits.maxBytes) +
                                " bytes in all");
    // Count the fields sent so far: a flood of short fields is refused before its end.
    size_t lines = size_t(std::count(rest.begin(), rest.begin() + headBytes, '\n'));
    size_t fieldsSoFar = lines > 1 ? lines - 1 : 0;
    if (end != std::string_view::npos) fieldsSoFar = lines - 2;
    if (fieldsSoFar > limits.maxFields)
        return refused(431, "the request has more than " + std::to_string(limits.maxFields) + " header fields");
    if (end == std::string_view::npos) return {};

    HeadScan scan;
    std::string_view head = rest.substr(0, end + 2);  // each line with its CRLF
    for (size_t i = 0; i < head.size(); ++i) {
        bool crlf = head[i] == '\r' && i + 1 < head.size() && head[i + 1] == '\n';
        if (crlf) ++i;
        else if (head[i] == '\r' || head[i] == '\n' || head[i] == '\0')
            return refused(400, "the request's head holds a bare CR, LF or NUL (lines end in CRLF)");
    }
    size_t pos = head.find(kCrlf);
    if (!parseRequestLine(head.substr(0, pos), scan.head))
        return refused(400, "malformed request line (expected METHOD TARGET HTTP/1.1)");
    for (pos += 2; pos < head.size();) {
        size_t next = head.find(kCrlf, pos);
        std::string_view line = head.substr(pos, next - pos);
        pos = next + 2;
        if (line.front() == ' ' || line.front() == '\t')
            return refused(400, "obsolete line folding in a header field");
        size_t colon = line.find(':');
        if (colon == std::string_view::npos || !isToken(line.substr(0, colon)))
            return refused(400, "malformed header field \"" + std::string(line.substr(0, 64)) + "\"");
        scan.head.fields.emplace_back(line.substr(0, colon), trimmed(line.substr(colon + 1)));
    }
    scan.state = HeadScan::State::Complete;
    scan.length = start + end + 4;
    return scan;
}

std::string forwardedHead(const RequestHead& head, const std::string& clientAddress) {
    std::string out = head.method + ' ' + head.target + ' ' + head.version + "\r\n";
    std::string empty;
    for (const auto& [name, value] : head.fields) {
        if (equalsIgnoringCase(name, kClientAddressField) || equalsIgnoringCase(name, kEmptyFieldsField)) continue;
        if (value.empty()) empty += (empty.empty() ? "" : ", ") + name;
        else out += name + ": " + value + "\r\n";
    }
    out += std::string(kClientAddressField) + ": " + clientAddress + "\r\n";
    if (!empty.empty()) out += std::string(kEmptyFieldsField) + ": " + empty + "\r\n";
    return out + "\r\n";
}

}  // namespace photon::api
