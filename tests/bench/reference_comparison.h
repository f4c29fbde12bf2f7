// SPPM on a scene with a reference image (another renderer's converged render, e.g.
// Tungsten's for the Bitterli scenes) at equal times: for each time, two renders with
// different seeds give the relative noise (RMS of their difference / sqrt 2 / mean), the bias
// of the mean against the reference's, and the RMSE against the reference over its mean
// (photon-bench --compare-reference FILE --seconds 10,30). The render is at the scene's size
// when the reference's is a whole multiple of it (the reference box-averaged down), else at
// the reference's. Pixels where the reference is
// brighter than 25 times its mean (a light seen directly or in a mirror) are left out of
// every figure: their values follow the reference renderer's pixel filter, not transport.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include <photon/scene_file.h>

namespace photon::bench {

nlohmann::json compareWithReference(const std::string& sceneFile, const std::string& referenceFile,
                                    const std::vector<double>& seconds,
                                    const std::vector<SettingOverride>& overrides = {});

}  // namespace photon::bench
