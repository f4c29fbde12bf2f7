// One interface of a camera's lens system (pbrt-v4's RealisticCamera lens files), front
// (object side) first, in millimetres: the radius of curvature (positive with its centre
// toward the film; 0 for the aperture stop, a plane), the distance along the axis to the next
// interface (the last: to the film, which focusing sets), the index of refraction behind it
// (toward the film; 0 or 1 for air) and its aperture's diameter.
#pragma once

namespace photon {

struct LensInterface {
    double radius, thickness, eta, apertureDiameter;
};

}  // namespace photon
