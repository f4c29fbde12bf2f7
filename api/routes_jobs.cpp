// /api/v1/jobs: submit, list, inspect, cancel, delete.
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <charconv>
#include <climits>
#include <filesystem>
#include "api/guard_fields.h"
#include "api/errors.h"
#include "api/handlers.h"
#include "api/job_json.h"
#include "api/params.h"
#include "api/upload_reader.h"
#include "server/job_labels.h"

namespace photon::api {

namespace {

constexpr int64_t kDefaultPageSize = 50;
constexpr int64_t kMaxPageSize = 1000;

server::SubmitOptions submitOptions(const httplib::Request& req) {
    server::SubmitOptions o;
    // Ranges here only reject nonsense; the server limits (422) are checked with the scene.
    o.passes = integerParam(req, "passes", 1, INT64_MAX);
    o.photonsPerPass = integerParam(req, "photons_per_pass", 1, INT64_MAX);
    o.seed = unsignedParam(req, "seed");
    o.targetError = numberParam(req, "target_error", 0, 1e9);
    o.camera = stringParam(req, "camera");
    o.lenient = booleanParam(req, "lenient");
    o.priority = int(integerParam(req, "priority", INT_MIN, INT_MAX).value_or(0));
    o.name = stringParam(req, "name").value_or("");
    o.labels = stringParams(req, "label");
    return o;
}

// Query parameters first, then the form's fields; the name defaults to the scene file's.
void addFormFields(server::SubmitOptions& options, const httplib::Request& req, const UploadFields& fields) {
    if (!req.has_param("name")) options.name = fields.name.value_or(server::nameFromSceneFile(fields.sceneFileName));
    if (!req.has_param("camera") && fields.camera) options.camera = fields.camera;
    if (!req.has_param("lenient") && fields.lenient) {
        if (*fields.lenient != "true" && *fields.lenient != "false") throwBadRequest("form field lenient: must be true or false");
        options.lenient = *fields.lenient == "true";
    }
    options.labels.insert(options.labels.end(), fields.labels.begin(), fields.labels.end());
}

// The query takes part in the request digest: the same body with other overrides is a
// different request. httplib keeps parameters sorted by name.
void addQuery(const httplib::Request& req, server::RequestDigest& digest) {
    for (const auto& [name, value] : req.params) {
        digest.add(name.data(), name.size());
        digest.endField();
        digest.add(value.data(), value.size());
        digest.endField();
    }
}

std::optional<std::string> idempotencyKey(const httplib::Request& req) {
    if (!req.has_header("Idempotency-Key") && !sentEmpty(req, "Idempotency-Key")) return std::nullopt;
    std::string key = req.get_header_value("Idempotency-Key");
    if (auto problem = server::idempotencyKeyProblem(key)) throwBadRequest(*problem);
    return key;
}

// status=queued,running (or status repeated), name= (a part of the name, any case),
// label= (each one the job must have), cursor= (from the last page's next_cursor).
server::JobFilter jobFilter(const httplib::Request& req) {
    server::JobFilter filter;
    for (const std::string& text : stringParams(req, "status")) {
        std::optional<server::JobStatus> status = server::parseJobStatus(text);
        if (!status)
            throwBadRequest("query parameter status: expected queued, running, paused, completed, failed or cancelled, got \"" +
                            text + "\"");
        filter.statuses.push_back(*status);
    }
    filter.nameContains = stringParam(req, "name").value_or("");
    filter.labels = stringParams(req, "label");
    if (std::optional<std::string> cursor = stringParam(req, "cursor")) {
        int64_t seq = 0;
        auto [end, ec] = std::from_chars(cursor->data(), cursor->data() + cursor->size(), seq);
        if (ec != std::errc() || end != cursor->data() + cursor->size() || seq < 1)
            throwBadRequest("query parameter cursor: not a cursor this server gave (next_cursor of a page)");
        filter.afterSeq = seq;
    }
    return filter;
}

// The request's own query with the cursor replaced, for the Link header (RFC 8288).
std::string nextPageLink(const httplib::Request& req, int64_t cursor) {
    std::string query;
    for (const auto& [key, value] : req.params)
        if (key != "cursor" && key != "offset") query += httplib::detail::encode_query_param(key) + "=" + httplib::detail::encode_query_param(value) + "&";
    return "<" + req.path + "?" + query + "cursor=" + std::to_string(cursor) + ">; rel=\"next\"";
}

// The media type of a stored scene file, by its name (server/job_folders.h).
std::string sceneContentType(const std::string& fileName) {
    const std::string extension = std::filesystem::path(fileName).extension().string();
    if (extension == ".pbrt") return "text/plain; charset=utf-8";
    if (extension == ".gltf") return "model/gltf+json";
    if (extension == ".glb") return "model/gltf-binary";
    return "application/json";
}

}  // namespace

void createJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res,
               const httplib::ContentReader& reader) {
    std::unique_ptr<server::StagedUpload> upload = ctx.service.newUpload();
    // The body is read before the query and headers are checked: an early answer would
    // leave the rest of the upload in the connection.
    const server::Limits& limits = ctx.service.limits();
    server::RequestDigest digest;
    UploadFields fields = readUpload(
        req, res, reader, *upload,
        {size_t(limits.maxBodyBytes), size_t(limits.maxSceneBytes), size_t(limits.maxUploadParts)}, digest);
    addQuery(req, digest);
    server::SubmitOptions options = submitOptions(req);
    addFormFields(options, req, fields);
    server::SubmitRequest request{options, clientAddress(req), idempotencyKey(req), digest.hex()};
    server::SubmitResult result = ctx.service.submit(*upload, request);
    res.set_header("Location", "/api/v1/jobs/" + result.job.id);
    // 200 for a retry: the job exists already and is what the first attempt created.
    sendJson(res, result.created ? 201 : 200, toJson(result.job));
}

void listJobs(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    server::JobFilter filter = jobFilter(req);
    int64_t limit = integerParam(req, "limit", 1, kMaxPageSize).value_or(kDefaultPageSize);
    int64_t offset = integerParam(req, "offset", 0, INT64_MAX).value_or(0);
    if (filter.afterSeq && offset != 0) throwBadRequest("query parameters cursor and offset: give one or the other");
    server::JobTable::Page page = ctx.service.list(filter, size_t(limit), size_t(offset));
    nlohmann::json jobs = nlohmann::json::array();
    for (const server::JobRecord& job : page.jobs) jobs.push_back(toJson(job));
    nlohmann::json next;
    if (page.nextAfterSeq) {
        next = std::to_string(*page.nextAfterSeq);
        res.set_header("Link", nextPageLink(req, *page.nextAfterSeq));
    }
    sendJson(res, 200, {{"jobs", std::move(jobs)}, {"total", page.total}, {"next_cursor", next}});
}

void getJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    sendJson(res, 200, toJson(ctx.service.get(pathId(req))));
}

// PATCH /api/v1/jobs/{id} {"priority": N}: what may change of a job after submission.
void updateJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    nlohmann::json body = nlohmann::json::parse(req.body);
    if (!body.is_object()) throwBadRequest("the body must be a JSON object such as {\"priority\": 5}");
    for (const auto& [key, value] : body.items())
        if (key != "priority") throwBadRequest("\"" + key + "\" cannot be changed; only \"priority\" can");
    if (!body.contains("priority")) throwBadRequest("nothing to change: give {\"priority\": N}");
    const nlohmann::json& priority = body["priority"];
    if (!priority.is_number_integer() || priority.get<int64_t>() < INT_MIN || priority.get<int64_t>() > INT_MAX)
        throwBadRequest("priority: must be a 32-bit integer");
    sendJson(res, 200, toJson(ctx.service.setPriority(pathId(req), priority.get<int>())));
}

// POST /api/v1/jobs/{id}/clone?passes=&photons_per_pass=&seed=&priority=&name=&label=
void cloneJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    server::SubmitResult result = ctx.service.clone(pathId(req), submitOptions(req), clientAddress(req));
    res.set_header("Location", "/api/v1/jobs/" + result.job.id);
    sendJson(res, 201, toJson(result.job));
}

// GET /api/v1/jobs/{id}/scene: the scene file as submitted, JSON or imported.
void getScene(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    const std::string id = pathId(req);
    res.set_content(ctx.service.scene(id), sceneContentType(ctx.service.sceneFileName(id)));
}

// POST /api/v1/jobs/{id}/pause: 200 when it paused at once (queued), 202 when a running
// render stops after its current pass (its events and status then say "paused").
void pauseJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    server::JobService::CancelResult result = ctx.service.pause(pathId(req));
    sendJson(res, result.pending ? 202 : 200, toJson(result.job));
}

void resumeJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    sendJson(res, 200, toJson(ctx.service.resume(pathId(req))));
}

// POST /api/v1/jobs/{id}/continue?passes=N: N more passes of a completed job.
void continueJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    std::optional<int64_t> passes = integerParam(req, "passes", 1, INT32_MAX);
    if (!passes) throwBadRequest("query parameter passes: give how many more passes to render");
    sendJson(res, 200, toJson(ctx.service.continueJob(pathId(req), *passes)));
}

// GET /api/v1/jobs/{id}/log: the job's own log, a line an event.
void getLog(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    res.set_content(ctx.service.log(pathId(req)), "text/plain; charset=utf-8");
}

// GET /api/v1/jobs/{id}/progress: the job's progress over its passes, for plots (at most 256
// points, thinned evenly; saved at most a second behind the render).
void getProgressHistory(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    nlohmann::json points = nlohmann::json::array();
    for (const server::ProgressPoint& p : ctx.service.progressHistory(pathId(req)))
        points.push_back({{"pass", p.pass},
                          {"elapsed_seconds", p.elapsedSeconds},
                          {"photons_traced", p.photonsTraced},
                          {"mean_radius", p.meanRadius},
                          {"relative_error", p.relativeError ? nlohmann::json(*p.relativeError) : nlohmann::json()}});
    sendJson(res, 200, {{"points", points}});
}

void cancelJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    server::JobService::CancelResult result = ctx.service.cancel(pathId(req));
    // 202: a running render stops at its next check; the events stream reports the end.
    sendJson(res, result.pending ? 202 : 200, toJson(result.job));
}

void deleteJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    ctx.service.remove(pathId(req));
    res.status = 204;
}

}  // namespace photon::api
