// f = (1 - t) f_a + t f_b at one surface point: the blend a mix material makes (mix.cpp) and
// the one between two precomputed roughness levels (textured_roughness.cpp). Sampling picks
// one part by its share and weights the sample by the whole mixture's eval and pdf
// (one-sample MIS with the balance heuristic, Veach 1997 sec. 9.2.4), so the estimate has no
// more variance than the better of the two allows.
#pragma once
#include "materials/material.h"

namespace photon {

class MaterialMixture {
public:
    // The parts with what each reads at the point, and t in [0, 1].
    MaterialMixture(const Material& a, const MaterialInputs& inA, const Material& b, const MaterialInputs& inB, float t)
        : a_(a), b_(b), inA_(inA), inB_(inB), t_(t) {}

    Color eval(Vec3 wo, Vec3 wi, TransportMode mode, unsigned lobes) const;
    float pdf(Vec3 wo, Vec3 wi, unsigned lobes) const;
    std::optional<BSDFSample> sample(Vec3 wo, float uLobe, Vec2 u, TransportMode mode, unsigned lobes) const;
    // The diffuse lobes' share, each part's own share weighted by its factor.
    float diffuseShare(Vec3 wo) const;

private:
    // The probability of sampling part a among the parts that have `lobes` (NaN if neither
    // has: then both "pa > 0" and "pa < 1" are false).
    float probabilityOfA(unsigned lobes) const;

    const Material &a_, &b_;
    MaterialInputs inA_, inB_;
    float t_;
};

}  // namespace photon
