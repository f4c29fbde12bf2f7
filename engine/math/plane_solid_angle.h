// The solid angle an axis-aligned rectangle [x0, x1] x [y0, y1] of the plane z = 1 subtends
// at the origin: from the corner function F(u, v) = atan(u v / sqrt(1 + u^2 + v^2)), the
// solid angle of [0, u] x [0, v] (Girard's theorem for the projected rectangle), by
// inclusion and exclusion. Exact for rectangles on either side of the axis.
#pragma once
#include <cmath>

namespace photon {

inline double cornerSolidAngle(double u, double v) { return std::atan2(u * v, std::sqrt(1 + u * u + v * v)); }

inline double rectangleSolidAngle(double x0, double x1, double y0, double y1) {
    return cornerSolidAngle(x1, y1) - cornerSolidAngle(x0, y1) - cornerSolidAngle(x1, y0) + cornerSolidAngle(x0, y0);
}

}  // namespace photon
