// /api/v1/jobs: submit, list, inspect, cancel, delete.
#include <httplib.h>
#include <climits>
#include "api/guard_fields.h"
#include "api/errors.h"
#include "api/handlers.h"
#include "api/job_json.h"
#include "api/params.h"
#include "api/upload_reader.h"

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
    o.priority = int(integerParam(req, "priority", INT_MIN, INT_MAX).value_or(0));
    return o;
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

std::optional<server::JobStatus> statusFilter(const httplib::Request& req) {
    std::optional<std::string> text = stringParam(req, "status");
    if (!text) return std::nullopt;
    std::optional<server::JobStatus> status = server::parseJobStatus(*text);
    if (!status) throwBadRequest("query parameter status: expected queued, running, completed, failed or cancelled");
    return status;
}

}  // namespace

void createJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res,
               const httplib::ContentReader& reader) {
    std::unique_ptr<server::StagedUpload> upload = ctx.service.newUpload();
    // The body is read before the query and headers are checked: an early answer would
    // leave the rest of the upload in the connection.
    const server::Limits& limits = ctx.service.limits();
    server::RequestDigest digest;
    readUpload(req, res, reader, *upload, {size_t(limits.maxBodyBytes), size_t(limits.maxSceneBytes), size_t(limits.maxUploadParts)}, digest);
    addQuery(req, digest);
    server::SubmitRequest request{submitOptions(req), clientAddress(req), idempotencyKey(req), digest.hex()};
    server::SubmitResult result = ctx.service.submit(*upload, request);
    res.set_header("Location", "/api/v1/jobs/" + result.job.id);
    // 200 for a retry: the job exists already and is what the first attempt created.
    sendJson(res, result.created ? 201 : 200, toJson(result.job));
}

void listJobs(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    std::optional<server::JobStatus> status = statusFilter(req);
    int64_t limit = integerParam(req, "limit", 1, kMaxPageSize).value_or(kDefaultPageSize);
    int64_t offset = integerParam(req, "offset", 0, INT64_MAX).value_or(0);
    server::JobTable::Page page = ctx.service.list(status, size_t(limit), size_t(offset));
    nlohmann::json jobs = nlohmann::json::array();
    for (const server::JobRecord& job : page.jobs) jobs.push_back(toJson(job));
    sendJson(res, 200, {{"jobs", std::move(jobs)}, {"total", page.total}});
}

void getJob(RouteContext& ctx, const httplib::Request& req, httplib::Response& res) {
    sendJson(res, 200, toJson(ctx.service.get(pathId(req))));
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
