// Density-estimation kernels shared by the photon integrators. Each is written as a
// weight k(t) of t = d^2 / r^2 normalised over its domain (below): an estimate on a disc
// then keeps the form sum(k Phi) / (pi r^2).
#pragma once
#include <cmath>
#include <photon/render_settings.h>

namespace photon {

// Where the photons are gathered: a disc on a surface, or a ball in a medium.
enum class KernelDomain { Disc, Ball };

// Normalised over the disc, (1 / pi) times the integral over the unit disc is 1; over the
// ball, the mean over the unit ball is 1 (an estimate there keeps the form
// sum(k Phi) / (4/3 pi r^3)). Biweight over the ball: the integral of (1 - s^2)^2 is
// 4 pi r^3 (1/3 - 2/5 + 1/7) = 4 pi r^3 8/105, so k = (35 / 8)(1 - t)^2; cone: of (1 - s),
// 4 pi r^3 / 12, so k = 4 (1 - sqrt(t)).
inline float kernelWeight(KernelKind kind, float d2OverR2, KernelDomain domain = KernelDomain::Disc) {
    const bool disc = domain == KernelDomain::Disc;
    switch (kind) {
        case KernelKind::Uniform: return 1.0f;
        case KernelKind::Biweight: {
            // Silverman's biweight (3 / pi)(1 - x^2)^2, times pi, on the disc.
            float t = 1.0f - d2OverR2;
            return (disc ? 3.0f : 4.375f) * t * t;
        }
        case KernelKind::Cone:
            // Jensen's cone filter w = 1 - d / (k r) with k = 1, divided by its integral
            // 1 - 2 / (3k) = 1/3 on the disc (Jensen 2001, sec. 7.2.1).
            return (disc ? 3.0f : 4.0f) * (1.0f - std::sqrt(d2OverR2));
    }
    return 1.0f;
}

}  // namespace photon
