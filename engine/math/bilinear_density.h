// A density on [0,1]^2 that is bilinear between four non-negative corner values, sampled by
// inversion: y from its linear marginal, then x from the linear conditional at y. Light
// samples use it to follow what a point of an area light brings to a receiver (its cosines
// and 1 / d^2 at the light's corners) where they would otherwise be uniform by area, as
// pbrt-v4 warps its triangle and bilinear-patch samples by the receiver's cosine at the
// corners (Hart, Pharr, Müller, Lopes, McGuire & Shirley 2020, "Practical Product Sampling
// by Fitting and Composing Warps").
#pragma once
#include <algorithm>
#include <cmath>
#include <photon/vec.h>

namespace photon {

// Corner values in the order (0,0), (1,0), (0,1), (1,1).
struct BilinearCorners {
    float w[4];
    float mean() const { return 0.25f * (w[0] + w[1] + w[2] + w[3]); }
    // The unnormalised value at u; over the square it integrates to mean().
    float at(Vec2 u) const {
        return (1 - u.x) * (1 - u.y) * w[0] + u.x * (1 - u.y) * w[1] + (1 - u.x) * u.y * w[2] + u.x * u.y * w[3];
    }
    // The density at u (1 over the square where every corner is 0: sampled uniformly).
    float density(Vec2 u) const {
        const float m = mean();
        return m > 0 ? at(u) / m : 1.0f;
    }
};

// A number in [0, 1) with density proportional to (1 - x) a + x b, from a uniform u; the
// form u (a + b) / (a + sqrt(lerp(u, a^2, b^2))) keeps its digits where a and b are close.
inline float sampleLinear(float u, float a, float b) {
    if (!(a + b > 0)) return u;
    const float x = u * (a + b) / (a + std::sqrt((1 - u) * a * a + u * b * b));
    return std::min(x, 0.99999994f);
}

inline Vec2 sampleBilinear(Vec2 u, const BilinearCorners& c) {
    if (!(c.mean() > 0)) return u;
    const float y = sampleLinear(u.y, c.w[0] + c.w[1], c.w[2] + c.w[3]);
    const float x = sampleLinear(u.x, (1 - y) * c.w[0] + y * c.w[2], (1 - y) * c.w[1] + y * c.w[3]);
    return {x, y};
}

}  // namespace photon
