// The light a medium emits toward o along the ray o + t d over [0, length]: the integral of
// T(t) sigma_a rho(t) Le(t) dt per channel (T the transmittance from o, rho the density,
// description/medium_emission.h), estimated from one point. The point is drawn on the segment in
// proportion to sigma_t rho T of one channel, picked uniformly among those with any
// extinction, and weighted by the mean of those channels' densities (one-sample multiple
// importance sampling, the balance heuristic, as free_flight.h weighs its flights): the
// density cancels, so the weight is sigma_a T Le over the channels' mean of
// sigma_t T / (1 - T(length)). Where the medium is optically thin the draw is close to
// uniform in the density's integral, where it is thick close to where the light escapes.
#pragma once
#include <cmath>
#include "description/scene_description.h"

namespace photon {

inline Color sampleEmissionAlong(const MediumDescription& m, Vec3 o, Vec3 d, float length, float u) {
    const Color sigmaT = m.extinction();
    const double total = m.densityLength(o, d, length);
    if (!(total > 0)) return Color(0.0f);
    int channels[3], k = 0;
    for (int c = 0; c < 3; ++c)
        if (sigmaT[c] > 0) channels[k++] = c;
    if (k == 0) return Color(0.0f);
    // The share of a channel's flights that end within the segment: 1 - T(length).
    auto ending = [&](int c) { return -std::expm1(-double(sigmaT[c]) * total); };
    u = std::min(u, 0x1.fffffep-1f);
    const int pick = std::min(static_cast<int>(u * float(k)), k - 1);
    const double v = double(u) * k - pick;
    const int c = channels[pick];
    const double depth = -std::log1p(-v * ending(c)) / sigmaT[c];
    float t = static_cast<float>(depth);
    if (m.density) {
        const DensityGrid::Reach r = m.density->reach(o, d, length, depth);
        if (!(r.t < length)) return Color(0.0f);  // rounding at the segment's end
        t = r.t;
    }
    const Color tr = m.transmittanceOver(depth);
    double pdf = 0;
    for (int j = 0; j < k; ++j) pdf += sigmaT[channels[j]] * tr[channels[j]] / ending(channels[j]);
    pdf /= k;
    if (!(pdf > 0)) return Color(0.0f);
    return m.absorption * tr * m.emission->at(o + d * t) / static_cast<float>(pdf);
}

}  // namespace photon
