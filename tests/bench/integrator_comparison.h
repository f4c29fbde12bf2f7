// Each integrator on one scene for the same time, against a long SPPM reference: the RMSE
// each reaches, as JSON (photon-bench --compare SECONDS).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace photon::bench {

// Renders `sceneFile` with every integrator for `seconds` each (the pass that crosses the
// time is finished) and with SPPM for `referenceSeconds`, and compares the images.
nlohmann::json compareIntegrators(const std::string& sceneFile, double seconds, double referenceSeconds);

}  // namespace photon::bench
