#include "api/sessions.h"
#include <algorithm>
#include <cstdio>
#include <random>

namespace photon::api {

bool constantTimeEquals(const std::string& given, const std::string& expected) {
    if (expected.empty()) return false;
    unsigned char diff = given.size() == expected.size() ? 0 : 1;
    for (size_t i = 0; i < given.size(); ++i)
        diff |= static_cast<unsigned char>(given[i] ^ expected[i % expected.size()]);
    return diff == 0;
}

std::string SessionStore::create() {
    std::random_device random;  // the kernel's generator (getrandom) on Linux
    std::string id;
    for (int i = 0; i < 8; ++i) {
        char hex[9];
        std::snprintf(hex, sizeof hex, "%08x", unsigned(random()));
        id += hex;
    }
    std::lock_guard lock(mutex_);
    dropExpired();
    if (sessions_.size() >= kMaxSessions) sessions_.pop_front();
    sessions_.push_back({id, std::chrono::steady_clock::now() + std::chrono::seconds(kSessionSeconds)});
    return id;
}

bool SessionStore::valid(const std::string& id) {
    std::lock_guard lock(mutex_);
    dropExpired();
    bool found = false;
    for (const Session& s : sessions_) found |= constantTimeEquals(id, s.id);  // no early exit
    return found;
}

void SessionStore::remove(const std::string& id) {
    std::lock_guard lock(mutex_);
    sessions_.erase(std::remove_if(sessions_.begin(), sessions_.end(), [&](const Session& s) { return s.id == id; }),
                    sessions_.end());
}

void SessionStore::dropExpired() {
    auto now = std::chrono::steady_clock::now();
    while (!sessions_.empty() && sessions_.front().expires <= now) sessions_.pop_front();
}

std::optional<std::string> SessionStore::idInCookies(const std::string& header) {
    // "a=1; photon_session=abc; b=2" (RFC 6265 section 4.2.1)
    const std::string name = std::string(kSessionCookie) + "=";
    for (size_t start = 0; start < header.size();) {
        size_t end = std::min(header.find(';', start), header.size());
        size_t first = header.find_first_not_of(' ', start);
        if (first < end && header.compare(first, name.size(), name) == 0)
            return header.substr(first + name.size(), end - first - name.size());
        start = end + 1;
    }
    return std::nullopt;
}

std::string SessionStore::setCookie(const std::string& id) {
    return std::string(kSessionCookie) + "=" + id + "; Path=/; Max-Age=" + std::to_string(kSessionSeconds) +
           "; HttpOnly; SameSite=Strict";
}

std::string SessionStore::clearCookie() {
    return std::string(kSessionCookie) + "=; Path=/; Max-Age=0; HttpOnly; SameSite=Strict";
}

}  // namespace photon::api
