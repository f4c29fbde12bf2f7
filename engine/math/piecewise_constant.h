// Piecewise-constant densities on [0,1) and [0,1)^2, sampled by inverting their CDFs (as
// pbrt-v4's PiecewiseConstant1D and PiecewiseConstant2D, appendix A): the 2D one as a
// marginal density over rows times a conditional density within each row. What
// environment maps sample their texels with.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>
#include <photon/vec.h>

namespace photon {

// n equal cells on [0,1) with non-negative weights; the density in cell i is
// weight_i / (mean weight). All-zero weights give the uniform density.
class PiecewiseConstant1D {
public:
    PiecewiseConstant1D() = default;
    explicit PiecewiseConstant1D(std::vector<float> weights) : weights_(std::move(weights)), cdf_(weights_.size() + 1) {
        const size_t n = weights_.size();
        double sum = 0;
        for (size_t i = 0; i < n; ++i) sum += std::max(weights_[i], 0.0f);
        allZero_ = !(sum > 0);
        if (allZero_) std::fill(weights_.begin(), weights_.end(), 1.0f), sum = double(n);
        // Accumulated in double, then rounded: a million cells summed in float would leave
        // the last CDF entries several ulps from 1.
        double running = 0;
        for (size_t i = 0; i < n; ++i) {
            weights_[i] = std::max(weights_[i], 0.0f);
            cdf_[i] = float(running / sum);
            running += weights_[i];
        }
        cdf_[n] = 1.0f;
        integral_ = float(sum / double(n));
    }

    size_t size() const { return weights_.size(); }
    // The mean of the weights: the integral of the step function they define over [0,1).
    float integral() const { return integral_; }
    // True if every weight was 0 (the density is then uniform).
    bool allZero() const { return allZero_; }
    // The density on the cell holding x (x in [0,1)).
    float pdf(size_t cell) const { return integral_ > 0 ? weights_[cell] / integral_ : 0.0f; }
    // The probability of cell i as a whole: pdf(i) / size().
    float cellProbability(size_t cell) const { return cdf_[cell + 1] - cdf_[cell]; }

    struct Sample {
        float x;      // in [0,1)
        size_t cell;  // the cell x fell in
        float pdf;    // density at x
    };
    // The x with CDF(x) = u: the cell by binary search, then linearly within it.
    Sample sample(float u) const {
        const size_t n = weights_.size();
        // The last cell whose CDF start is <= u. Rounding can leave u in a cell of weight 0
        // (CDF entries of trailing empty cells a few ulps below 1): the nearest cell with
        // weight is taken instead, so a sample never has density 0.
        size_t cell = size_t(std::upper_bound(cdf_.begin(), cdf_.end() - 1, u) - cdf_.begin());
        cell = std::clamp<size_t>(cell, 1, n) - 1;
        while (cell > 0 && !(weights_[cell] > 0)) --cell;
        while (cell + 1 < n && !(weights_[cell] > 0)) ++cell;
        const float width = cdf_[cell + 1] - cdf_[cell];
        float offset = width > 0 ? (u - cdf_[cell]) / width : 0.5f;
        offset = std::clamp(offset, 0.0f, 1.0f);
        float x = std::min((float(cell) + offset) / float(n), 0x1.fffffep-1f);
        return {x, cell, pdf(cell)};
    }

private:
    std::vector<float> weights_;
    std::vector<float> cdf_;  // size + 1 entries, cdf_[0] = 0, cdf_[size] = 1
    float integral_ = 0;
    bool allZero_ = false;
};

// width x height cells on [0,1)^2, row 0 at y in [0, 1/height); weights row-major.
class PiecewiseConstant2D {
public:
    PiecewiseConstant2D() = default;
    PiecewiseConstant2D(const std::vector<float>& weights, int width, int height) : width_(width), height_(height) {
        std::vector<float> rowIntegrals(static_cast<size_t>(height), 0.0f);
        rows_.reserve(size_t(height));
        for (int y = 0; y < height; ++y) {
            auto first = weights.begin() + ptrdiff_t(y) * width;
            rows_.emplace_back(std::vector<float>(first, first + width));
            rowIntegrals[size_t(y)] = rows_.back().integral();
        }
        // A row of zeros gets the uniform conditional from PiecewiseConstant1D, but its
        // marginal weight is 0, so it is never picked and its density is 0.
        for (int y = 0; y < height; ++y)
            if (rows_[size_t(y)].allZero()) rowIntegrals[size_t(y)] = 0;
        marginal_ = PiecewiseConstant1D(std::move(rowIntegrals));
    }

    int width() const { return width_; }
    int height() const { return height_; }
    // The mean weight over all cells.
    float integral() const { return marginal_.integral(); }

    struct Sample {
        Vec2 point;    // in [0,1)^2
        int x, y;      // the cell it fell in
        float pdf;     // density at the point, per unit area of [0,1)^2
    };
    Sample sample(Vec2 u) const {
        PiecewiseConstant1D::Sample row = marginal_.sample(u.y);
        PiecewiseConstant1D::Sample column = rows_[row.cell].sample(u.x);
        return {{column.x, row.x}, int(column.cell), int(row.cell), row.pdf * column.pdf};
    }
    // Density of cell (x, y) per unit area (the same at every point of the cell).
    float pdf(int x, int y) const { return marginal_.pdf(size_t(y)) * rows_[size_t(y)].pdf(size_t(x)); }
    // The probability of cell (x, y) as a whole.
    float cellProbability(int x, int y) const { return pdf(x, y) / (float(width_) * float(height_)); }

private:
    int width_ = 0, height_ = 0;
    std::vector<PiecewiseConstant1D> rows_;  // the conditional density within each row
    PiecewiseConstant1D marginal_;           // over rows, by each row's integral
};

}  // namespace photon
