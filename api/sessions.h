// Browser sessions for a server with a token: the page trades the token (as a bearer header)
// for a session cookie, so that what a browser fetches by itself, without a header it could
// add (EventSource streams, <img> and download links), is authorised too. The cookie is
// HttpOnly (no script reads it) and SameSite=Strict (no other site's page sends it); the
// server's Origin checks refuse cross-site changes besides.
//
// Sessions live in memory: a restart ends them and the page trades its token again. At most
// kMaxSessions exist (the oldest goes first), each for kSessionSeconds.
#pragma once
#include <chrono>
#include <deque>
#include <mutex>
#include <optional>
#include <string>

namespace photon::api {

inline constexpr const char* kSessionCookie = "photon_session";

// Compares without an early exit, so response time says nothing about how much of a
// guessed token or session id was right.
bool constantTimeEquals(const std::string& given, const std::string& expected);

class SessionStore {
public:
    static constexpr size_t kMaxSessions = 1024;
    static constexpr int kSessionSeconds = 24 * 3600;

    // A new session's id: 32 random bytes as hex.
    std::string create();
    bool valid(const std::string& id);
    void remove(const std::string& id);

    // The session id in a Cookie header value, if it names one.
    static std::optional<std::string> idInCookies(const std::string& cookieHeader);
    // Set-Cookie values that start and end a session.
    static std::string setCookie(const std::string& id);
    static std::string clearCookie();

private:
    struct Session {
        std::string id;
        std::chrono::steady_clock::time_point expires;
    };
    void dropExpired();

    std::mutex mutex_;
    std::deque<Session> sessions_;  // oldest first
};

}  // namespace photon::api
