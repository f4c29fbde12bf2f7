// The error heat map as a picture: what the page and the image route show for ?layer=error.
#pragma once
#include <optional>
#include <photon/image.h>

namespace photon {

// Each pixel's estimated relative error (the "error" layer's relative channel;
// docs/error-estimate.md) on a colour ramp in linear RGB, to be encoded at exposure 0: a
// logarithmic scale from 0.1% and below (black) through 1% (purple) and 10% (orange) to 100%
// and above (pale yellow), so that every factor of ten is a step one can see. Pixels without
// light are black. nullopt when the image has no "error" layer.
std::optional<Image> errorHeatMap(const LayeredImage& image);

// The ramp's colour for a relative error, linear RGB (exposed for tests and legends).
Color errorHeatMapColor(float relativeError);

}  // namespace photon
