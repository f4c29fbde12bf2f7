// A job's name and labels, as a client gives them at submission: the name says what the job
// is in lists ("cornell-box", "shot 12 take 3"); labels are short tags to find jobs by
// ("project=atrium", "draft"). Both are checked here, once, for every way they arrive.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace photon::server {

inline constexpr size_t kMaxNameBytes = 200;
inline constexpr size_t kMaxLabelBytes = 64;
inline constexpr size_t kMaxLabels = 16;

// Why `name` cannot be a job's name (too long, a control character, not UTF-8), or nullopt.
std::optional<std::string> jobNameProblem(const std::string& name);
// Why `labels` cannot be a job's labels: more than kMaxLabels, or one that is empty, too
// long or holds a character other than letters, digits and . _ - : = /. nullopt if fine.
std::optional<std::string> jobLabelsProblem(const std::vector<std::string>& labels);
// A scene file's name as a job name: "scenes/cornell-box.json" -> "cornell-box".
std::string nameFromSceneFile(const std::string& fileName);

}  // namespace photon::server
