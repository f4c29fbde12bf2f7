#include "job.h"
#include <array>

namespace photon::server {

namespace {

constexpr std::array<std::pair<JobStatus, const char*>, 6> kNames{{
    {JobStatus::Queued, "queued"},
    {JobStatus::Running, "running"},
    {JobStatus::Paused, "paused"},
    {JobStatus::Completed, "completed"},
    {JobStatus::Failed, "failed"},
    {JobStatus::Cancelled, "cancelled"},
}};

}  // namespace

const char* toString(JobStatus status) {
    for (const auto& [s, name] : kNames)
        if (s == status) return name;
    return "unknown";
}

std::optional<JobStatus> parseJobStatus(const std::string& text) {
    for (const auto& [s, name] : kNames)
        if (text == name) return s;
    return std::nullopt;
}

bool isFinished(JobStatus status) {
    return status == JobStatus::Completed || status == JobStatus::Failed || status == JobStatus::Cancelled;
}

void MethodFigures::update(const PassStats& pass) {
    if (pass.patches > 0) {
        patches = pass.patches;
        solverIterations = pass.solverIterations;
        solverResidual = pass.solverResidual;
    }
    if (pass.globalMapPhotons > 0 || pass.causticMapPhotons > 0) {
        globalMapPhotons = pass.globalMapPhotons;
        causticMapPhotons = pass.causticMapPhotons;
    }
}

}  // namespace photon::server
