// Service-level routes: health check, what the server offers, Prometheus metrics, the
// placeholder home page.
#include <httplib.h>
#include <photon/render_settings.h>
#include <algorithm>
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

// What a client need not guess: the server's version, the integrators a scene may name, and
// every limit with its value here (the options' names, "--max-pixels" as "max_pixels").
void info(RouteContext& ctx, const httplib::Request&, httplib::Response& res) {
    nlohmann::json limits = nlohmann::json::object();
    for (const server::LimitOption& limit : server::limitOptions()) {
        std::string name = std::string(limit.option).substr(2);
        std::replace(name.begin(), name.end(), '-', '_');
        limits[name] = ctx.service.limits().*limit.field;
    }
    sendJson(res, 200,
             {{"version", PHOTON_VERSION},
              {"integrators", std::vector<std::string>(kIntegratorNames.begin(), kIntegratorNames.end())},
              {"limits", limits}});
}

// The render farm's workers (docs/scale-out.md): empty, with "farm": false, when the server
// renders everything itself.
void listWorkers(RouteContext& ctx, const httplib::Request&, httplib::Response& res) {
    std::optional<server::FarmFigures> farm = ctx.service.farmFigures();
    nlohmann::json workers = nlohmann::json::array();
    if (farm)
        for (const server::FarmFigures::Worker& w : farm->workers)
            workers.push_back({{"name", w.name},
                               {"host", w.host},
                               {"threads", w.threads},
                               {"busy", w.busy},
                               {"job", w.job.empty() ? nlohmann::json(nullptr) : nlohmann::json(w.job)},
                               {"passes_per_second", w.passesPerSecond},
                               {"batches", w.batches},
                               {"redeliveries", w.claimed}});
    sendJson(res, 200,
             {{"farm", farm.has_value()}, {"queue_depth", farm ? farm->queueDepth : 0}, {"workers", workers}});
}

void metrics(RouteContext& ctx, const httplib::Request&, httplib::Response& res) {
    res.set_content(ctx.service.metrics().prometheusText(ctx.service.jobCounts(), ctx.service.farmFigures()),
                    "text/plain; version=0.0.4");
}

void homePage(RouteContext&, const httplib::Request&, httplib::Response& res) {
    res.set_content(kHomePage, "text/html; charset=utf-8");
}

}  // namespace photon::api
