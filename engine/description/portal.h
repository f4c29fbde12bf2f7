// A portal (LightDescription::portal): four corners in order forming a rectangle. What is
// wrong with them, if anything, for the scene readers' errors.
#pragma once
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <photon/vec.h>

namespace photon {

inline std::optional<std::string> portalProblem(const std::array<Vec3, 4>& q) {
    const Vec3 a = q[3] - q[0], b = q[1] - q[0];
    if (!(length(a) > 0) || !(length(b) > 0) || !std::isfinite(length(a) + length(b)))
        return "the corners must span a rectangle of non-zero area";
    if (std::abs(dot(normalize(a), normalize(b))) > 1e-3f)
        return "must be a rectangle: the edges from the first corner are not at right angles";
    if (length(q[2] - (q[1] + a)) > 1e-3f * std::max(length(a), length(b)))
        return "must be a rectangle: the third corner is not opposite the first";
    return std::nullopt;
}

}  // namespace photon
