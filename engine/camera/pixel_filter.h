// Pixel reconstruction filters (pbrt-v4 sec. 8.8): a pixel's value is the image weighted by
// the filter centred on it, f(d) / integral(f), d the offset from the pixel's centre. Each
// camera sample is drawn from the filter itself (filter importance sampling; Ernst et al.
// 2006, pbrt-v4 sec. 8.8.2), so that every pixel stays an independent mean of its own
// samples, as SPPM's visible points and the error estimate need: a sample at offset d
// weighs f(d) / (p(d) integral(f)), exactly 1 for the box and the triangle (sampled by
// inverting their distributions) and near 1 for the others (sampled from a table of their
// cells' integrals: up to about 2 in the cells where the filter falls to 0; unbiased).
//
// Every filter here is separable, f(x, y) = f(x) f(y). Estimates are non-negative in
// photon (shared-exponent colours, visible points' throughputs), so the Mitchell and
// Lanczos filters' negative lobes are left out: f = max(f, 0) on each axis.
#pragma once
#include <photon/vec.h>
#include "description/pixel_filter_description.h"
#include "math/piecewise_constant.h"

namespace photon {

class PixelFilter {
public:
    explicit PixelFilter(const PixelFilterDescription& d = {});

    struct Sample {
        Vec2 offset;  // from the pixel's centre, in pixels
        float weight;
    };
    Sample sample(Vec2 u) const;
    // f(offset) / integral(f): what a pixel's value weighs the image at `offset` by.
    float normalised(Vec2 offset) const { return x_.normalised(offset.x) * y_.normalised(offset.y); }
    // The unit box, whose samples are the pixel's own square: film position x + u exactly.
    bool unitBox() const { return unitBox_; }

private:
    class Axis {
    public:
        Axis() = default;
        Axis(const PixelFilterDescription& d, float radius);
        // The offset and its weight f / (p integral(f)).
        std::pair<float, float> sample(float u) const;
        float value(float x) const;  // f(x), negative lobes cut to 0
        float normalised(float x) const { return value(x) / integral_; }

    private:
        PixelFilterDescription::Kind kind_ = PixelFilterDescription::Kind::Box;
        float radius_ = 0.5f, sigma_ = 0.5f, b_ = 1.0f / 3.0f, c_ = 1.0f / 3.0f, tau_ = 3.0f;
        float integral_ = 1.0f;
        PiecewiseConstant1D cells_;  // for the kinds without an inverse: each cell's integral
    };
    Axis x_, y_;
    bool unitBox_ = true;
};

}  // namespace photon
