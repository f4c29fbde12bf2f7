// The JSON form of a job record, shared by every route that returns jobs and by the event
// stream (api/openapi.yaml, schema Job).
#pragma once
#include <nlohmann/json.hpp>
#include "server/job.h"

namespace httplib {
struct Response;
}

namespace photon::api {

nlohmann::json toJson(const server::JobRecord& job);
void sendJson(httplib::Response& res, int status, const nlohmann::json& body);

}  // namespace photon::api
