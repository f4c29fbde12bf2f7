#include "math/density_grid.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace photon {

namespace {
// The trilinear interpolation of a cell's eight corners c[k], k = x + 2 y + 4 z, at (fx, fy, fz).
double trilinear(const float c[8], double fx, double fy, double fz) {
    const double x00 = c[0] + (c[1] - c[0]) * fx, x10 = c[2] + (c[3] - c[2]) * fx;
    const double x01 = c[4] + (c[5] - c[4]) * fx, x11 = c[6] + (c[7] - c[6]) * fx;
    const double y0 = x00 + (x10 - x00) * fy, y1 = x01 + (x11 - x01) * fy;
    return y0 + (y1 - y0) * fz;
}

// The integral of a cubic f over [a, b], exact (Simpson's rule).
template <class F>
double simpson(const F& f, double a, double b) {
    return (b - a) / 6.0 * (f(a) + 4.0 * f(0.5 * (a + b)) + f(b));
}
}  // namespace

DensityGrid::DensityGrid(int nx, int ny, int nz, std::vector<float> values, const Transform& latticeFromWorld)
    : n_{nx, ny, nz}, values_(std::move(values)), latticeFromWorld_(latticeFromWorld) {
    if (nx < 1 || ny < 1 || nz < 1 || values_.size() != static_cast<size_t>(nx) * ny * nz)
        throw std::invalid_argument("density grid: nx * ny * nz values needed");
    for (float v : values_) {
        if (!(v >= 0) || !std::isfinite(v)) throw std::invalid_argument("density grid: values must be finite and >= 0");
        max_ = std::max(max_, v);
    }
}

DensityGrid::DensityGrid(int nx, int ny, int nz, std::shared_ptr<const Samples> samples, float maxValue,
                         const Transform& latticeFromWorld)
    : n_{nx, ny, nz}, samples_(std::move(samples)), latticeFromWorld_(latticeFromWorld), max_(maxValue) {
    if (nx < 1 || ny < 1 || nz < 1 || !samples_) throw std::invalid_argument("density grid: no samples");
}

Transform DensityGrid::latticeFromBox(int nx, int ny, int nz, Vec3 p0, Vec3 p1) {
    const Vec3 scale{static_cast<float>(nx) / (p1.x - p0.x), static_cast<float>(ny) / (p1.y - p0.y),
                     static_cast<float>(nz) / (p1.z - p0.z)};
    return Transform::translate(Vec3(-0.5f)) * Transform::scale(scale) * Transform::translate(-p0);
}

void DensityGrid::corners(int i, int j, int k, float c[8]) const {
    if (samples_) [[unlikely]] {
        samples_->corners(i, j, k, n_, c);
        return;
    }
    for (int corner = 0; corner < 8; ++corner) {
        const int x = i + (corner & 1), y = j + ((corner >> 1) & 1), z = k + (corner >> 2);
        const bool inside = x >= 0 && y >= 0 && z >= 0 && x < n_[0] && y < n_[1] && z < n_[2];
        c[corner] = inside ? values_[(static_cast<size_t>(z) * n_[1] + y) * n_[0] + x] : 0.0f;
    }
}

float DensityGrid::at(Vec3 p) const {
    const Vec3 u = latticeFromWorld_.point(p);
    if (!(u.x >= -0.5f && u.y >= -0.5f && u.z >= -0.5f && u.x <= n_[0] - 0.5f && u.y <= n_[1] - 0.5f &&
          u.z <= n_[2] - 0.5f))
        return 0.0f;
    const int i = static_cast<int>(std::floor(u.x)), j = static_cast<int>(std::floor(u.y)), k = static_cast<int>(std::floor(u.z));
    float c[8];
    corners(i, j, k, c);
    return static_cast<float>(trilinear(c, u.x - i, u.y - j, u.z - k));
}

template <class Visit>
void DensityGrid::walk(Vec3 o, Vec3 d, float length, Visit&& visit) const {
    const Vec3 uo = latticeFromWorld_.point(o), uv = latticeFromWorld_.vector(d);
    const double u0[3] = {uo.x, uo.y, uo.z}, v[3] = {uv.x, uv.y, uv.z};
    // The density is zero outside the box, (-1/2, n - 1/2) on each axis: the line's part inside.
    double tEnter = 0, tExit = length;
    for (int a = 0; a < 3; ++a) {
        const double lo = -0.5, hi = n_[a] - 0.5;
        if (v[a] == 0) {
            if (!(u0[a] > lo && u0[a] < hi)) return;
            continue;
        }
        double t0 = (lo - u0[a]) / v[a], t1 = (hi - u0[a]) / v[a];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0), tExit = std::min(tExit, t1);
    }
    if (!(tEnter < tExit)) return;
    // The cells from the one the line enters (Amanatides & Woo 1987).
    int cell[3], step[3];
    double tNext[3], tDelta[3];
    const double tMid = tEnter + 1e-9 * std::max(1.0, tExit - tEnter);
    for (int a = 0; a < 3; ++a) {
        cell[a] = std::clamp(static_cast<int>(std::floor(u0[a] + v[a] * tMid)), -1, n_[a] - 1);
        if (v[a] > 0) {
            step[a] = 1, tNext[a] = (cell[a] + 1 - u0[a]) / v[a], tDelta[a] = 1 / v[a];
        } else if (v[a] < 0) {
            step[a] = -1, tNext[a] = (cell[a] - u0[a]) / v[a], tDelta[a] = -1 / v[a];
        } else {
            step[a] = 0, tNext[a] = tDelta[a] = std::numeric_limits<double>::infinity();
        }
    }
    for (double t = tEnter; t < tExit;) {
        const int a = tNext[0] < tNext[1] ? (tNext[0] < tNext[2] ? 0 : 2) : (tNext[1] < tNext[2] ? 1 : 2);
        const double tEnd = std::min(tNext[a], tExit);
        if (tEnd > t) {
            const int i = cell[0], j = cell[1], k = cell[2];
            float c[8];
            corners(i, j, k, c);
            auto density = [&](double s) {
                return trilinear(c, std::clamp(u0[0] + v[0] * s - i, 0.0, 1.0), std::clamp(u0[1] + v[1] * s - j, 0.0, 1.0),
                                 std::clamp(u0[2] + v[2] * s - k, 0.0, 1.0));
            };
            if (!visit(t, tEnd, density)) return;
        }
        t = tEnd;
        cell[a] += step[a];
        tNext[a] += tDelta[a];
        if (cell[a] < -1 || cell[a] > n_[a] - 1) return;
    }
}

double DensityGrid::integral(Vec3 o, Vec3 d, float length) const {
    double sum = 0;
    walk(o, d, length, [&](double a, double b, const auto& density) {
        sum += simpson(density, a, b);
        return true;
    });
    return sum;
}

DensityGrid::Reach DensityGrid::reach(Vec3 o, Vec3 d, float length, double depth) const {
    double reached = std::numeric_limits<double>::infinity(), sum = 0;
    walk(o, d, length, [&](double a, double b, const auto& density) {
        const double cell = simpson(density, a, b);
        if (sum + cell < depth) {
            sum += cell;
            return true;
        }
        // The cumulative depth in the cell is a quartic, increasing: Newton's method kept
        // inside a shrinking bracket (bisection where a step would leave it).
        const double need = depth - sum;
        double lo = a, hi = b, t = a + (b - a) * std::clamp(need / cell, 0.0, 1.0);
        for (int iteration = 0; iteration < 60 && hi - lo > 1e-12 * std::max(1.0, std::abs(b)); ++iteration) {
            const double g = simpson(density, a, t) - need;
            if (g == 0) break;
            (g > 0 ? hi : lo) = t;
            const double slope = density(t);
            const double newton = slope > 0 ? t - g / slope : lo;
            t = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
        }
        reached = t;
        return false;
    });
    return std::isinf(reached) ? Reach{std::numeric_limits<float>::infinity(), sum} : Reach{static_cast<float>(reached), depth};
}

}  // namespace photon
