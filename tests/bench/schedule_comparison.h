// SPPM's two radius schedules at equal time (photon-bench --compare-schedules SECONDS): the
// per-pixel one (Hachisuka & Jensen 2009) and the global one whose passes are independent
// (Knaus & Zwicker 2011, what the render farm splits), each rendered twice with two seeds
// and against a long per-pixel reference: relative noise (RMS of the seeds' difference /
// sqrt 2 / mean), bias of the mean, and RMSE, as JSON.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace photon::bench {

nlohmann::json compareRadiusSchedules(const std::string& sceneFile, double seconds, double referenceSeconds);

}  // namespace photon::bench
