#include "film/error_decay.h"
#include <algorithm>
#include <cmath>

namespace photon {

namespace {
constexpr double kMinSpan = 1.4;      // the passes' ratio the fitted points must span
constexpr size_t kMinPoints = 4;
constexpr double kSpacing = 1.01;     // least ratio between kept points
constexpr double kMinDecay = 0.1, kMaxDecay = 1.5;
}  // namespace

void ErrorDecay::add(int64_t passes, double relativeError) {
    if (passes <= 0 || !(relativeError > 0) || !std::isfinite(relativeError)) return;
    if (!points_.empty() && passes == points_.back().passes) {  // the same passes again
        points_.back().error = relativeError;
        return;
    }
    if (!points_.empty() && passes < points_.back().passes) points_.clear();  // restarted
    if (!points_.empty() && double(passes) < kSpacing * double(points_.back().passes)) return;
    points_.push_back({passes, relativeError});
    const double half = 0.5 * double(passes);
    const auto firstKept = std::find_if(points_.begin(), points_.end(), [&](const Point& p) { return double(p.passes) >= half; });
    points_.erase(points_.begin(), firstKept);
}

std::optional<double> ErrorDecay::measured() const {
    if (points_.size() < kMinPoints) return std::nullopt;
    if (double(points_.back().passes) < kMinSpan * double(points_.front().passes)) return std::nullopt;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Point& p : points_) {
        const double x = std::log(double(p.passes)), y = std::log(p.error);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double n = double(points_.size());
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return std::clamp(-slope, kMinDecay, kMaxDecay);
}

double passesToTarget(double passes, double error, double target, double decay) {
    return error <= target ? 0.0 : passes * std::pow(error / target, 1 / decay) - passes;
}

}  // namespace photon
