// Light a medium emits (pbrt-v4's media with "Le", "Lescale" and "temperature"): per unit
// length of a ray, sigma_a(p) Le(p) (the medium's absorption at p, its density included,
// times the radiance it emits there), the source term of the radiative transfer equation
// (Pharr, Jakob & Humphreys, 4th ed., eq. 11.1). Le(p) is `radiance`, times the `scale`
// grid where there is one, times where a `temperature` grid is given pbrt-v4's blackbody
// spectrum (its peak 1) at (T(p) - offset) * temperatureScale kelvin, none at or below 100 K
// (pbrt-v4's cut-off).
#pragma once
#include <memory>
#include "math/density_grid.h"
#include <photon/vec.h>

namespace photon {

struct MediumEmission {
    Color radiance{1.0f};
    std::shared_ptr<const DensityGrid> scale;
    std::shared_ptr<const DensityGrid> temperature;
    float temperatureOffset = 0;
    float temperatureScale = 1;

    // Le at world point p.
    Color at(Vec3 p) const;
    // Le where the temperature is t kelvin before the offset and scale (radiance where no
    // temperature grid is given).
    Color atTemperature(float t) const;
    // The grid that says where the medium emits: temperature, else scale (none: wherever
    // the medium's density is, MediumDescription::emissionRegion).
    const std::shared_ptr<const DensityGrid>& grid() const { return temperature ? temperature : scale; }
};

}  // namespace photon
