#include "job_labels.h"
#include <algorithm>
#include <cctype>
#include <filesystem>

namespace photon::server {

namespace {

// Well-formed UTF-8 (RFC 3629), no control characters: a name is shown as text everywhere.
bool isPrintableUtf8(const std::string& s) {
    for (size_t i = 0; i < s.size();) {
        unsigned char c = static_cast<unsigned char>(s[i]);
        if (c < 0x20 || c == 0x7f) return false;
        size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        if (length == 0 || i + length > s.size()) return false;
        for (size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
        i += length;
    }
    return true;
}

bool isLabelChar(unsigned char c) {
    return std::isalnum(c) || std::string_view("._-:=/").find(char(c)) != std::string_view::npos;
}

}  // namespace

std::optional<std::string> jobNameProblem(const std::string& name) {
    if (name.size() > kMaxNameBytes)
        return "name: " + std::to_string(name.size()) + " bytes, longer than " + std::to_string(kMaxNameBytes);
    if (!isPrintableUtf8(name)) return "name: must be UTF-8 text without control characters";
    return std::nullopt;
}

std::optional<std::string> jobLabelsProblem(const std::vector<std::string>& labels) {
    if (labels.size() > kMaxLabels)
        return "label: " + std::to_string(labels.size()) + " labels, more than " + std::to_string(kMaxLabels);
    for (const std::string& label : labels) {
        if (label.empty() || label.size() > kMaxLabelBytes)
            return "label \"" + label.substr(0, kMaxLabelBytes) + "\": must be 1 to " + std::to_string(kMaxLabelBytes) +
                   " characters";
        if (!std::all_of(label.begin(), label.end(), [](unsigned char c) { return isLabelChar(c); }))
            return "label \"" + label + "\": only letters, digits and . _ - : = / may be used";
    }
    return std::nullopt;
}

std::string nameFromSceneFile(const std::string& fileName) {
    std::string stem = std::filesystem::path(fileName).stem().string();
    return jobNameProblem(stem) ? std::string() : stem;
}

}  // namespace photon::server
