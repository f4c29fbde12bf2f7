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

// Two renders made elsewhere (another renderer, another build of photon) that differ by their
// seed alone, scored as compareWithReference scores its own: the same figures by the same
// code, so that a table can hold photon and its peers side by side (photon-bench
// --compare-reference REF --score-pair A.exr,B.exr). The reference is box-averaged down to
// the renders' size when it is a whole multiple of it. Throws std::invalid_argument when the
// sizes do not fit.
nlohmann::json scoreRenderPair(const std::string& firstFile, const std::string& secondFile,
                               const std::string& referenceFile);

// A named set of settings the scene is rendered with (photon-bench --variant NAME:KEY=VALUE).
struct SceneVariant {
    std::string name;
    std::vector<SettingOverride> overrides;
};
// The variants from photon-bench's -D KEY=VALUE settings (every variant's) and --variant
// NAME:KEY=VALUE ones, in the order their names first appear; with no --variant, one
// variant, "scene", of the -D settings alone. Throws std::invalid_argument on a malformed one.
std::vector<SceneVariant> parseVariants(const std::vector<std::string>& common, const std::vector<std::string>& variants);
// compareWithReference for each variant: {"scene", "reference", "variants": [{"name",
// "settings", and compareWithReference's fields}]}.
nlohmann::json compareVariantsWithReference(const std::string& sceneFile, const std::string& referenceFile,
                                            const std::vector<double>& seconds,
                                            const std::vector<SceneVariant>& variants);
// That result as a Markdown table, a row per variant and time.
std::string markdownTable(const nlohmann::json& result);

}  // namespace photon::bench
