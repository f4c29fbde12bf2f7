// The directional albedo E(cos theta) of a clear dielectric coat seen from outside: the
// share of light arriving at that angle that the coat reflects, Fresnel's F(cos) when it is
// smooth, the GGX + Fresnel lobe's albedo when it is rough (tabulated). 1 - E is what it
// lets through, in or out. Shared by the coated materials (coated_diffuse.cpp,
// coated_conductor.cpp).
#pragma once
#include <array>
#include "materials/microfacet.h"

namespace photon {

class CoatAlbedo {
public:
    // ior: the coat's index n_coat / n_outside; ggx: its roughness (smooth() for none).
    CoatAlbedo(float ior, GGX ggx);

    float operator()(float cosTheta) const;
    // Ebar = 2 int_0^1 E(mu) mu dmu: the coat's albedo for diffuse light from outside.
    float cosineWeighted() const { return cosineWeighted_; }

private:
    static constexpr int kTableSize = 64;
    static float tableCosine(int k);
    float integrateRough(float mu) const;

    float ior_;
    GGX ggx_;
    std::array<float, kTableSize> table_{};
    float cosineWeighted_ = 0;
};

}  // namespace photon
