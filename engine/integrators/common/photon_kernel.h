// Density-estimation kernels shared by the photon integrators. Each is written as a
// weight k(t) of t = d^2 / r^2 normalised so that (1 / pi) times its integral over the
// unit disc is 1: an estimate then keeps the form sum(k Phi) / (pi r^2).
#pragma once
#include <cmath>
#include <photon/render_settings.h>

namespace photon {

inline float kernelWeight(KernelKind kind, float d2OverR2) {
    switch (kind) {
        case KernelKind::Uniform: return 1.0f;
        case KernelKind::Biweight: {
            // Silverman's biweight (3 / pi)(1 - x^2)^2, times pi.
            float t = 1.0f - d2OverR2;
            return 3.0f * t * t;
        }
        case KernelKind::Cone:
            // Jensen's cone filter w = 1 - d / (k r) with k = 1, divided by its integral
            // 1 - 2 / (3k) = 1/3 (Jensen 2001, sec. 7.2.1).
            return 3.0f * (1.0f - std::sqrt(d2OverR2));
    }
    return 1.0f;
}

}  // namespace photon
