#include "math/windowed_piecewise_constant.h"
#include <algorithm>
#include <cmath>

namespace photon {

WindowedPiecewiseConstant2D::WindowedPiecewiseConstant2D(const std::vector<float>& weights, int n)
    : n_(n), weights_(weights), sat_(size_t(n + 1) * size_t(n + 1), 0.0) {
    const double cellArea = 1.0 / (double(n) * double(n));
    for (float& w : weights_) w = std::max(w, 0.0f);
    for (int y = 0; y < n; ++y) {
        double row = 0;
        for (int x = 0; x < n; ++x) {
            row += double(weight(x, y)) * cellArea;
            sat_[size_t(y + 1) * size_t(n + 1) + size_t(x + 1)] = table(x + 1, y) + row;
        }
    }
}

int WindowedPiecewiseConstant2D::cellOf(double x) const { return std::clamp(int(std::floor(x * n_)), 0, n_ - 1); }

WindowedPiecewiseConstant2D::Split WindowedPiecewiseConstant2D::split(double x) const {
    const double s = std::clamp(x, 0.0, 1.0) * n_;
    const int i = std::min(int(s), n_ - 1);
    return {i, s - i};
}

double WindowedPiecewiseConstant2D::along(int column, Split y) const {
    const double a = table(column, y.cell);
    return a + y.fraction * (table(column, y.cell + 1) - a);
}

double WindowedPiecewiseConstant2D::integral(const UvWindow& w) const {
    const Split u0 = split(w.lo.x), u1 = split(w.hi.x), v0 = split(w.lo.y), v1 = split(w.hi.y);
    // The window's marginal at column line c, M(c) = I(c / n, v1) - I(c / n, v0), is linear
    // in u between column lines, as the integral is.
    auto marginal = [&](Split u) {
        const double a = along(u.cell, v1) - along(u.cell, v0);
        return a + u.fraction * (along(u.cell + 1, v1) - along(u.cell + 1, v0) - a);
    };
    return std::max(0.0, marginal(u1) - marginal(u0));
}

namespace {

// The x in [lo, hi] (as fractions of n cells) where a nondecreasing function, linear
// between the cell lines, reaches target; at(k) is its value at line k. The cell by binary
// search over the lines the window spans, then a linear solve in it.
template <typename At>
std::pair<double, int> invert(const At& at, double lo, double hi, int n, double target) {
    int first = std::clamp(int(std::floor(lo * n)), 0, n - 1), last = std::clamp(int(std::ceil(hi * n)) - 1, first, n - 1);
    while (first < last) {  // the last cell whose starting line is at or below target
        const int mid = (first + last + 1) / 2;
        if (at(mid) <= target) first = mid;
        else last = mid - 1;
    }
    const double a = at(first), b = at(first + 1);
    double x = (double(first) + (b > a ? std::clamp((target - a) / (b - a), 0.0, 1.0) : 0.5)) / n;
    const double cellEnd = std::nextafter(std::min(hi, double(first + 1) / n), lo);
    x = std::clamp(x, std::max(lo, double(first) / n), std::max(lo, cellEnd));
    return {x, first};
}

}  // namespace

std::optional<WindowedPiecewiseConstant2D::Sample> WindowedPiecewiseConstant2D::sample(Vec2 u, const UvWindow& w) const {
    const Split su0 = split(w.lo.x), su1 = split(w.hi.x), sv0 = split(w.lo.y), sv1 = split(w.hi.y);
    auto atLine = [&](int c) { return along(c, sv1) - along(c, sv0); };
    auto marginal = [&](Split s) { return atLine(s.cell) + s.fraction * (atLine(s.cell + 1) - atLine(s.cell)); };
    const double start = marginal(su0), total = marginal(su1) - start;
    if (!(total > 0)) return std::nullopt;
    // Named, not a structured binding: the lambdas below capture the column.
    const std::pair<double, int> inU = invert(atLine, w.lo.x, w.hi.x, n_, start + double(u.x) * total);
    const double x = inU.first;
    const int column = inU.second;
    // Within that column the density in v is the column's own cells.
    auto columnAt = [&](int row) { return table(column + 1, row) - table(column, row); };
    auto columnAlong = [&](Split s) { return columnAt(s.cell) + s.fraction * (columnAt(s.cell + 1) - columnAt(s.cell)); };
    const double low = columnAlong(sv0), columnTotal = columnAlong(sv1) - low;
    if (!(columnTotal > 0)) return std::nullopt;
    const auto [y, row] = invert(columnAt, w.lo.y, w.hi.y, n_, low + double(u.y) * columnTotal);
    const float density = float(double(weight(column, row)) / total);
    if (!(density > 0)) return std::nullopt;
    return Sample{{float(x), float(y)}, density};
}

float WindowedPiecewiseConstant2D::pdf(Vec2 uv, const UvWindow& w) const {
    if (uv.x < w.lo.x || uv.x > w.hi.x || uv.y < w.lo.y || uv.y > w.hi.y) return 0;
    const double total = integral(w);
    if (!(total > 0)) return 0;
    return float(double(weight(cellOf(uv.x), cellOf(uv.y))) / total);
}

}  // namespace photon
