// Service-level routes: health check, Prometheus metrics, the placeholder home page.
#include <httplib.h>
#include "api/handlers.h"
#include "api/job_json.h"

namespace photon::api {

namespace {

// Until the web client (web/dist, served as static files when present) exists.
const char* kHomePage = R"html(<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><title>photon render service</title></head>
<body>
<h1>photon render service</h1>
<p>The web interface is not built yet. The REST API lives under <code>/api/v1</code>:
see <a href="/api/v1/jobs">/api/v1/jobs</a>.</p>
</body>
</html>
)html";

}  // namespace

void health(RouteContext&, const httplib::Request&, httplib::Response& res) { sendJson(res, 200, {{"status", "ok"}}); }

void metrics(RouteContext& ctx, const httplib::Request&, httplib::Response& res) {
    res.set_content(ctx.service.metrics().prometheusText(ctx.service.jobCounts()), "text/plain; version=0.0.4");
}

void homePage(RouteContext&, const httplib::Request&, httplib::Response& res) {
    res.set_content(kHomePage, "text/html; charset=utf-8");
}

}  // namespace photon::api
