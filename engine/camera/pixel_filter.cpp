#include "camera/pixel_filter.h"
#include <cmath>
#include <vector>
#include "math/sampling.h"

namespace photon {

namespace {

using Kind = PixelFilterDescription::Kind;

// Cells per pixel of radius in the tables of the filters sampled from one: 64, twice
// pbrt-v4's. On the Gaussian of radius 1.5 a sample at its centre weighs 1.0007; only in
// the few cells where the filter falls to 0 (its radius, a cut lobe) do single samples weigh
// up to about 2 (tests/test_pixel_filter.cpp), their mean over the table being 1.
constexpr int kCellsPerPixel = 64;
// Points per cell in the midpoint rule for each cell's integral.
constexpr int kPointsPerCell = 8;

float gaussian(float x, float sigma) {
    return std::exp(-x * x / (2 * sigma * sigma)) / std::sqrt(2 * kPi * sigma * sigma);
}

// Mitchell and Netravali 1988, on [-2, 2] (pbrt-v4's MitchellFilter::Mitchell1D).
float mitchell(float x, float b, float c) {
    x = std::abs(x);
    if (x <= 1) return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
    if (x <= 2)
        return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + (8 * b + 24 * c)) / 6;
    return 0;
}

float sinc(float x) { return std::abs(x) < 1e-5f ? 1.0f : std::sin(kPi * x) / (kPi * x); }

}  // namespace

PixelFilter::Axis::Axis(const PixelFilterDescription& d, float radius)
    : kind_(d.kind), radius_(radius), sigma_(d.sigma), b_(d.b), c_(d.c), tau_(d.tau) {
    if (kind_ == Kind::Box) {
        integral_ = 2 * radius_;
        return;
    }
    if (kind_ == Kind::Triangle) {
        integral_ = radius_ * radius_;
        return;
    }
    const int n = std::max(32, static_cast<int>(std::ceil(kCellsPerPixel * radius_)));
    const double width = 2.0 * radius_ / n;
    std::vector<float> means(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        double sum = 0;
        for (int k = 0; k < kPointsPerCell; ++k)
            sum += value(static_cast<float>(-radius_ + width * (i + (k + 0.5) / kPointsPerCell)));
        means[static_cast<size_t>(i)] = static_cast<float>(sum / kPointsPerCell);
    }
    cells_ = PiecewiseConstant1D(std::move(means));
    // The cells' mean value times the support: the integral the table's density is of.
    integral_ = 2 * radius_ * cells_.integral();
}

float PixelFilter::Axis::value(float x) const {
    if (std::abs(x) > radius_) return 0;
    switch (kind_) {
        case Kind::Box: return 1;
        case Kind::Triangle: return radius_ - std::abs(x);
        case Kind::Gaussian: return std::max(gaussian(x, sigma_) - gaussian(radius_, sigma_), 0.0f);
        case Kind::Mitchell: return std::max(mitchell(2 * x / radius_, b_, c_), 0.0f);
        case Kind::Lanczos: return std::max(sinc(x) * sinc(x / tau_), 0.0f);
    }
    return 0;
}

std::pair<float, float> PixelFilter::Axis::sample(float u) const {
    if (kind_ == Kind::Box) return {radius_ * (2 * u - 1), 1.0f};
    if (kind_ == Kind::Triangle) {
        // Each half of the tent with probability 1/2, by inverting its CDF.
        if (u < 0.5f) return {radius_ * (std::sqrt(2 * u) - 1), 1.0f};
        return {radius_ * (1 - std::sqrt(std::max(2 - 2 * u, 0.0f))), 1.0f};
    }
    const PiecewiseConstant1D::Sample s = cells_.sample(u);
    const float x = radius_ * (2 * s.x - 1);
    // f / (p integral): p = pdf / (2 radius), integral = 2 radius mean, so f / (pdf mean).
    const float density = s.pdf * cells_.integral();
    return {x, density > 0 ? value(x) / density : 0.0f};
}

PixelFilter::PixelFilter(const PixelFilterDescription& d)
    : x_(d, d.radius.x), y_(d, d.radius.y),
      unitBox_(d.kind == PixelFilterDescription::Kind::Box && d.radius.x == 0.5f && d.radius.y == 0.5f) {}

PixelFilter::Sample PixelFilter::sample(Vec2 u) const {
    const auto [x, wx] = x_.sample(u.x);
    const auto [y, wy] = y_.sample(u.y);
    return {{x, y}, wx * wy};
}

}  // namespace photon
