#include "description/medium_emission.h"
#include <array>
#include <cmath>
#include "math/spectrum_rgb.h"

namespace photon {

namespace {
// pbrt-v4's BlackbodySpectrum, projected once every 10 K up to 40,000 K and linear between:
// 4,000 projections at first use instead of one a look-up. Between two entries the colour
// moves by at most 0.2% of its value below 1,000 K and far less above, so the linear
// interpolation's error is below 1e-5 of it.
constexpr double kStep = 10, kTableEnd = 40000;
Color blackbodyPeakTabled(double kelvin) {
    static const std::array<Color, 4001> table = [] {
        std::array<Color, 4001> t{};
        for (size_t i = 1; i < t.size(); ++i) t[i] = blackbodyPeakColor(double(i) * kStep);
        return t;
    }();
    if (kelvin >= kTableEnd) return blackbodyPeakColor(kelvin);
    const double x = kelvin / kStep;
    const size_t i = static_cast<size_t>(x);
    const float f = static_cast<float>(x - double(i));
    return table[i] * (1 - f) + table[i + 1] * f;
}
}  // namespace

Color MediumEmission::atTemperature(float t) const {
    if (!temperature) return radiance;
    const double kelvin = (double(t) - temperatureOffset) * temperatureScale;
    if (!(kelvin > 100)) return Color(0.0f);
    return radiance * blackbodyPeakTabled(kelvin);
}

Color MediumEmission::at(Vec3 p) const {
    Color le = temperature ? atTemperature(temperature->at(p)) : radiance;
    if (scale) le *= scale->at(p);
    return le;
}

}  // namespace photon
