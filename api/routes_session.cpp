// POST and DELETE /api/v1/session: a browser session cookie for the token (sessions.h).
// Reaching the handler means the request was authorised (its bearer token, or a session).
#include <httplib.h>
#include "api/handlers.h"
#include "api/sessions.h"

namespace photon::api {

void startSession(RouteContext& ctx, const httplib::Request&, httplib::Response& res) {
    res.status = 204;
    // Without a token there is nothing to trade it for.
    if (ctx.tokenRequired) res.set_header("Set-Cookie", SessionStore::setCookie(ctx.sessions.create()));
}

void endSession(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    if (std::optional<std::string> id = SessionStore::idInCookies(req.get_header_value("Cookie")))
        ctx.sessions.remove(*id);
    res.status = 204;
    res.set_header("Set-Cookie", SessionStore::clearCookie());
}

}  // namespace photon::api
