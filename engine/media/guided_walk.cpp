#include "media/guided_walk.h"
#include <algorithm>
#include <array>

namespace photon {

namespace {

constexpr int kTableSteps = 256;

// The root of a nu / 2 ln((nu + 1) / (nu - 1)) = 1 by bisection on 1 / nu in (0, 1): the
// left side falls from infinity (nu -> 1) to a (nu -> infinity) as nu grows.
double solveEigenvalue(double albedo) {
    double lo = 0, hi = 1;  // 1 / nu
    for (int i = 0; i < 80; ++i) {
        const double x = 0.5 * (lo + hi), nu = 1 / x;
        const double f = albedo * nu / 2 * std::log((nu + 1) / (nu - 1));
        (f > 1 ? hi : lo) = x;  // f > 1: nu too small, 1 / nu too large
    }
    return 1 / (0.5 * (lo + hi));
}

// 1 / nu0 at s = sqrt(1 - a) = k / kTableSteps.
const std::array<float, kTableSteps + 1>& inverseEigenvalues() {
    static const std::array<float, kTableSteps + 1> table = [] {
        std::array<float, kTableSteps + 1> t{};
        t[0] = 0;  // a = 1: nu0 infinite
        for (int k = 1; k <= kTableSteps; ++k) {
            const double s = double(k) / kTableSteps, a = std::max(1e-6, 1 - s * s);
            t[size_t(k)] = float(1 / solveEigenvalue(a));
        }
        return t;
    }();
    return table;
}

}  // namespace

float dwivediEigenvalue(float albedo) {
    const float s = std::sqrt(std::clamp(1.0f - albedo, 0.0f, 1.0f)) * kTableSteps;
    const int k = std::min(static_cast<int>(s), kTableSteps - 1);
    const auto& t = inverseEigenvalues();
    const float inverse = t[size_t(k)] + (t[size_t(k) + 1] - t[size_t(k)]) * (s - float(k));
    // Kept off 1 (albedo 0: the density would be a spike at mu = 1) and off infinity.
    return std::clamp(1.0f / std::max(inverse, 1e-4f), 1.0001f, 1e4f);
}

}  // namespace photon
