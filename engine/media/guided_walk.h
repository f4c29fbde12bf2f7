// Walks under a surface guided back toward it (the zero-variance-based scheme of Krivanek &
// d'Eon 2014, "A Zero-variance-based Sampling Scheme for Monte Carlo Subsurface Scattering",
// after Dwivedi 1982). In a deep medium of high albedo a walk that only follows the phase
// function wanders for hundreds of events before it leaves; the light that reaches the
// camera is carried mostly by walks that turn back toward the surface they came in by. A
// guided step draws its direction with density falling off away from the surface normal n,
//     p(mu) = 1 / ((nu0 - mu) ln((nu0 + 1) / (nu0 - 1))),   mu = cos(direction, n),
// and its flight on the stretched extinction sigma_t (1 - mu / nu0), longer toward the surface,
// shorter away; nu0 is Dwivedi's eigenvalue of the albedo. Each step is guided with
// probability kGuidedProbability (3/4: against 1/2 and 0.9, the least noise at equal time on
// a Skin1 ball and on scenes/subsurface.json, docs/sppm.md) and otherwise classical (the phase
// function and sigma_t),
// and weighed by the mixture of the two (one-sample multiple importance sampling, balance
// heuristic), channel by channel with the path's chromatic weights (free_flight.h): every
// step keeps its expectation, so the walk stays unbiased.
#pragma once
#include <cmath>
#include <photon/vec.h>

namespace photon {

// Dwivedi's eigenvalue nu0 > 1 for single-scattering albedo a in (0, 1): the root of
// a nu0 / 2 ln((nu0 + 1) / (nu0 - 1)) = 1 (isotropic scattering), from a table in
// sqrt(1 - a), where 1 / nu0 is smooth (about sqrt(3 (1 - a)) near a = 1).
float dwivediEigenvalue(float albedo);

// How the step under way was drawn, for its flight's weight (sampleFreeFlight).
struct GuidedStep {
    static constexpr float kGuidedProbability = 0.75f;
    bool on = false;      // the next flight is a guided walk's step
    bool guided = false;  // drawn toward the surface (else by the phase function)
    float mu = 0;         // cos between its direction and the surface normal
    float phase = 0;      // the phase function's density of its direction
    Color nu0{2.0f};      // Dwivedi's eigenvalue of each channel's albedo
    // The guided direction's density for each channel's eigenvalue.
    Color guideDensity() const {
        Color p;
        for (int c = 0; c < 3; ++c) p[c] = muDensity(mu, nu0[c]) * (0.5f / 3.14159265358979f);
        return p;
    }
    // The guided flight's extinction in channel c.
    float stretched(float sigmaT, int c) const { return sigmaT * (1.0f - mu / nu0[c]); }
    static float muDensity(float mu, float nu0) {
        return 1.0f / ((nu0 - mu) * static_cast<float>(std::log((nu0 + 1.0) / (nu0 - 1.0))));
    }
    // mu drawn with density muDensity by inverting its distribution: u = 0 gives -1, u = 1 gives 1.
    static float sampleMu(float u, float nu0) {
        const double r = (nu0 - 1.0) / (nu0 + 1.0);
        return static_cast<float>(std::clamp(nu0 - (nu0 + 1.0) * std::pow(r, static_cast<double>(u)), -1.0, 1.0));
    }
};

}  // namespace photon
