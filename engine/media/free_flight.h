// Where a path's ray first scatters in a homogeneous medium, if before the end of its
// segment. A medium's extinction may differ by colour channel; one channel per path, its
// hero, draws every distance of that path, and the path carries each channel's density over
// the hero's, by which its throughput is weighted: one-sample multiple importance sampling
// over the channels for the whole path (the balance heuristic; pbrt-v4's VolPathIntegrator
// and its r_u, after Miller, Georgiev & Jarosz 2019). Weighting each flight on its own by
// the mean of the channels' densities is unbiased too, but its weights multiply along a
// path: in a white furnace of fog with extinction (1, 2, 4) the blue channel's mean over
// 64 x 64 paths was 0.94 (1024 x 64: 0.976) where it must be 1.
#pragma once
#include <cmath>
#include <limits>
#include "description/scene_description.h"
#include "media/guided_walk.h"

namespace photon {

// What a path carries through media: its hero channel (-1 until its first flight in a
// medium that scatters) and each channel's path density over the hero's, scaled to mean 1.
struct ChromaticFlight {
    int hero = -1;
    Color ratios{1.0f};
};

// In a homogeneous medium, the distance sampleFreeFlight draws with u for `path` (before it
// is cut at the segment's end): known before the segment is, so a ray need only be cast that
// far (castPastBoundaries).
inline float homogeneousFlightDistance(const MediumDescription& m, float u, const ChromaticFlight& path,
                                       const GuidedStep* step = nullptr) {
    int h = path.hero;
    if (h < 0) {
        h = std::min(static_cast<int>(u * 3), 2);
        u = u * 3 - static_cast<float>(h);
    }
    u = std::min(u, 0x1.fffffep-1f);
    const float sigmaT = step && step->on && step->guided ? step->stretched(m.extinction()[h], h) : m.extinction()[h];
    return sigmaT > 0 ? static_cast<float>(-std::log1p(-static_cast<double>(u)) / sigmaT)
                      : std::numeric_limits<float>::infinity();
}

// Weighs a path by a flight whose density in each channel over the hero's is `density` and
// whose contribution over the hero's density is `weight`: beta = f / mean(r) over the path,
// the old mean being 1.
inline void weighFlight(Color density, Color weight, Color& beta, ChromaticFlight& path) {
    const Color ratios = path.ratios * density;
    const float mean = (ratios.x + ratios.y + ratios.z) / 3;
    if (!(mean > 0)) {
        beta = Color(0.0f);
        return;
    }
    beta = beta * weight / mean;
    path.ratios = ratios / mean;
}

// Samples the free flight of the ray o + t d (|d| = 1) over a segment of `length`
// (infinite if the ray leaves the scene) in medium m with the number u in [0, 1) (the
// path's first flight also picks its hero with it). Returns the distance at which the ray
// scatters, below `length`, or `length`; beta is then weighted so that its expected value,
// over the flight and the hero, is sigma_s T(t) at a scattering point's density and
// T(length) at the end. In a medium of varying density the flight is drawn exactly on the
// density's integral D(t) (DensityGrid::reach): T = exp(-sigma_t D), the density at the
// point cancelling from the weight, so one number still draws a flight.
// With a guided walk's `step` (guided_walk.h; homogeneous media only) the flight is drawn on
// the strategy the step's direction was drawn with, and weighed by the mixture of both
// strategies' densities of direction and flight together.
inline float sampleFreeFlight(const MediumDescription& m, Vec3 o, Vec3 dir, float length, float u, Color& beta,
                              ChromaticFlight& path, const GuidedStep* step = nullptr) {
    if (step && step->on && path.hero >= 0 && !m.density) {
        const Color sigmaT = m.extinction();
        const int h = path.hero;
        u = std::min(u, 0x1.fffffep-1f);
        const float used = step->guided ? step->stretched(sigmaT[h], h) : sigmaT[h];
        const double flight = used > 0 ? -std::log1p(-static_cast<double>(u)) / used : std::numeric_limits<double>::infinity();
        const bool scatters = flight < length;
        const float d = scatters ? static_cast<float>(flight) : length;
        // Per channel: a flight's density on extinction s, to d (scattering) or past it.
        auto flightDensity = [&](float s) { return scatters ? s * std::exp(-s * d) : std::exp(-s * d); };
        const Color guide = step->guideDensity();
        Color density, weight;
        for (int c = 0; c < 3; ++c) {
            density[c] = (1 - GuidedStep::kGuidedProbability) * step->phase * flightDensity(sigmaT[c]) +
                         GuidedStep::kGuidedProbability * guide[c] * flightDensity(step->stretched(sigmaT[c], c));
            const float tr = std::exp(-sigmaT[c] * d);
            weight[c] = step->phase * (scatters ? m.scattering[c] * tr : tr);
        }
        const float hero = density[h];
        if (!(hero > 0)) {
            beta = Color(0.0f);
            return d;
        }
        weighFlight(density / hero, weight / hero, beta, path);
        return d;
    }
    if (path.hero < 0) {
        path.hero = std::min(static_cast<int>(u * 3), 2);
        u = u * 3 - static_cast<float>(path.hero);
    }
    u = std::min(u, 0x1.fffffep-1f);
    const Color sigmaT = m.extinction();
    const int h = path.hero;
    // The density's integral the flight travels before it scatters, on the hero's extinction.
    const double depth = sigmaT[h] > 0 ? -std::log1p(-static_cast<double>(u)) / sigmaT[h]
                                       : std::numeric_limits<double>::infinity();
    float t;
    double travelled;  // the density's integral up to where the flight ends
    if (m.density) {
        const DensityGrid::Reach r = m.density->reach(o, dir, length, depth);
        t = r.t, travelled = r.depth;
    } else {
        t = static_cast<float>(depth), travelled = depth;
    }
    const bool scatters = t < length;
    const float d = scatters ? t : length;
    if (!scatters && !m.density) travelled = length;
    const Color tr = m.transmittanceOver(travelled);
    // Each channel's density of this flight over the hero's, and the contribution's.
    const float hero = scatters ? sigmaT[h] * tr[h] : tr[h];
    const Color density = (scatters ? sigmaT * tr : tr) / hero;
    const Color weight = (scatters ? m.scattering * tr : tr) / hero;
    weighFlight(density, weight, beta, path);
    return d;
}

}  // namespace photon
