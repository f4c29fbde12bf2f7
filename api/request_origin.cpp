#include "api/request_origin.h"
#include <httplib.h>
#include <algorithm>
#include <cctype>

namespace photon::api {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// "name:port", "[v6]:port", "name" or "[v6]" into the name (brackets off) and the port (0
// when absent; -1 when it is not a number).
struct HostPort {
    std::string name;
    int port = 0;
};
HostPort splitHost(const std::string& text) {
    HostPort hp;
    size_t colon = std::string::npos;
    if (!text.empty() && text[0] == '[') {
        size_t close = text.find(']');
        hp.name = text.substr(1, close == std::string::npos ? std::string::npos : close - 1);
        if (close != std::string::npos && close + 1 < text.size() && text[close + 1] == ':') colon = close + 1;
    } else {
        colon = text.rfind(':');
        hp.name = text.substr(0, colon);
    }
    if (colon != std::string::npos) {
        const std::string digits = text.substr(colon + 1);
        hp.port = !digits.empty() && digits.size() <= 5 && std::all_of(digits.begin(), digits.end(), ::isdigit)
                      ? std::stoi(digits)
                      : -1;
    }
    hp.name = lower(hp.name);
    return hp;
}

bool isLoopbackName(const std::string& name) {
    return name == "localhost" || name == "::1" || name.rfind("127.", 0) == 0;
}
bool isWildcard(const std::string& name) { return name.empty() || name == "0.0.0.0" || name == "::"; }

bool hostAllowed(const std::string& header, const OriginPolicy& policy) {
    const HostPort host = splitHost(header);
    if (host.port < 0) return false;
    for (const std::string& entry : policy.allowedHosts) {
        const HostPort allowed = splitHost(entry);
        if (allowed.name == host.name && (allowed.port == 0 || allowed.port == host.port)) return true;
    }
    const std::string bound = lower(policy.boundHost);
    if (isWildcard(bound)) return policy.allowedHosts.empty();
    // The names the listening address answers to, at the listening port (a browser leaves
    // the port out only for 80).
    const bool portMatches = host.port == policy.port || (host.port == 0 && policy.port == 80);
    if (!portMatches) return false;
    return host.name == bound || (isLoopbackName(bound) && isLoopbackName(host.name));
}

bool changesState(const std::string& method) { return method != "GET" && method != "HEAD" && method != "OPTIONS"; }

bool hasBody(const httplib::Request& req) {
    if (req.has_header("Transfer-Encoding")) return true;
    const std::string length = req.get_header_value("Content-Length");
    return !length.empty() && length != "0";
}

}  // namespace

std::optional<Refusal> checkRequestOrigin(const httplib::Request& req, const OriginPolicy& policy) {
    const std::string host = req.get_header_value("Host");
    if (req.has_header("Host") && !hostAllowed(host, policy))
        return Refusal{421, "this server does not answer to the host name \"" + host +
                                "\" (--allow-host names more, e.g. for a reverse proxy)"};
    if (changesState(req.method)) {
        const std::string origin = req.get_header_value("Origin");
        const bool listed = std::find(policy.allowedOrigins.begin(), policy.allowedOrigins.end(), origin) !=
                            policy.allowedOrigins.end();
        const bool sameOrigin = !host.empty() && (origin == "http://" + host || origin == "https://" + host);
        if (req.has_header("Origin") && !sameOrigin && !listed)
            return Refusal{403, "requests from " + origin + " may not change anything here (--allow-origin lists "
                                "the sites that may)"};
        const std::string site = req.get_header_value("Sec-Fetch-Site");
        if (!site.empty() && site != "same-origin" && site != "none" && !listed)
            return Refusal{403, "a " + site + " request may not change anything here (--allow-origin lists the "
                                "sites that may)"};
        if (hasBody(req)) {
            std::string type = lower(req.get_header_value("Content-Type"));
            type = type.substr(0, type.find(';'));
            type.erase(type.find_last_not_of(" \t") + 1);
            if (type != "application/json" && type != "multipart/form-data")
                return Refusal{415, "a request body must be application/json or multipart/form-data, not \"" +
                                        req.get_header_value("Content-Type") + "\""};
        }
    }
    return std::nullopt;
}

}  // namespace photon::api
