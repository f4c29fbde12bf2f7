// Russian roulette for photon paths, shared by the photon integrators.
#pragma once
#include <optional>
#include "math/rng.h"
#include <photon/vec.h>

namespace photon {

// A photon with throughput `beta` scattered with BSDF weight f cos / pdf: it survives with
// probability q = max(beta * weight) / max(beta), the largest colour channel, and then
// carries (beta * weight) / q, so surviving photons keep about the flux they had (Jensen
// 2001, sec. 5.2; pbrt-v4's SPPM). nullopt: absorbed, or a throughput that is no use.
inline std::optional<Color> photonAfterRoulette(Color beta, Color weight, Rng& rng) {
    Color next = beta * weight;
    float q = maxComponent(next) / maxComponent(beta);
    if (q < 1) {
        if (rng.uniform() >= q) return std::nullopt;
        next /= q;
    }
    if (!(maxComponent(next) > 0) || !isFinite(next)) return std::nullopt;
    return next;
}

}  // namespace photon
