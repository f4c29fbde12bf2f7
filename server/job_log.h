// A job's own log (DIR/jobs/<id>/job.log): one line per thing that happened to it, with its
// time in UTC: accepted with its settings and warnings, started or resumed, a checkpoint
// discarded, a priority changed, finished and how. What a user asks "what happened to my
// job?" about, apart from the server's own log. Served by GET /api/v1/jobs/{id}/log.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

namespace photon::server {

// Lines past this size are dropped (a job has a bounded number of events; this is a guard).
inline constexpr std::uintmax_t kMaxJobLogBytes = 1 << 20;

// Appends "<UTC time> <line>\n". Never throws: a log line that cannot be written (a full
// disk, say) must not fail the job it is about.
void appendJobLog(const std::filesystem::path& file, const std::string& line);

}  // namespace photon::server
