// A piecewise-constant density on [0,1)^2 that can be sampled within any axis-aligned
// window of it, for portal-masked environment light (lights/portal_environment_light.cpp),
// where each shading point sees the sky through its own rectangle of directions.
//
// Built on a summed-area table of the cells' integrals: the integral over [0,u] x [0,v] is
// the table's bilinear interpolation (exact for a piecewise-constant density), so the
// window's marginal in u is piecewise linear and is inverted by a binary search over
// columns and a linear solve within one, and the conditional in v likewise within that
// column (Bitterli et al. 2015, "Portal-Masked Environment Map Sampling"; pbrt-v4's
// WindowedPiecewiseConstant2D samples its windows the same way).
#pragma once
#include <optional>
#include <vector>
#include <photon/vec.h>

namespace photon {

struct UvWindow {
    Vec2 lo, hi;  // lo <= hi, within [0,1]^2
};

class WindowedPiecewiseConstant2D {
public:
    WindowedPiecewiseConstant2D() = default;
    // n x n cells, weights row-major (row = v), non-negative.
    WindowedPiecewiseConstant2D(const std::vector<float>& weights, int n);

    // The integral of the density's weights over the window (0 if all zero there).
    double integral(const UvWindow& w) const;

    struct Sample {
        Vec2 uv;
        float pdf;  // density per unit area of uv, within the window
    };
    // A point of the window with density weight / integral(window); none if that is 0.
    std::optional<Sample> sample(Vec2 u, const UvWindow& w) const;
    // The density sample(., w) draws uv with (0 outside the window).
    float pdf(Vec2 uv, const UvWindow& w) const;

    int size() const { return n_; }
    float weight(int x, int y) const { return weights_[size_t(y) * size_t(n_) + size_t(x)]; }

private:
    // A coordinate in cells: the cell it falls in and how far along it.
    struct Split {
        int cell;
        double fraction;
    };
    Split split(double x) const;
    // The integral over [0, column / n] x [0, y].
    double along(int column, Split y) const;
    double table(int x, int y) const { return sat_[size_t(y) * size_t(n_ + 1) + size_t(x)]; }
    int cellOf(double x) const;

    int n_ = 0;
    std::vector<float> weights_;
    std::vector<double> sat_;  // (n+1)^2: integral over [0, x/n] x [0, y/n]
};

}  // namespace photon
