// pbrt-v4's RealisticCamera lens files, and the thin lens a lenient import keeps of them: the
// system's paraxial focal length and its aperture stop.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace photon::pbrt {

// One row of a lens file, in millimetres, front (object side) first: the interface's radius
// of curvature (positive with its centre toward the film; 0 for the aperture stop, a plane),
// the distance along the axis to the next interface (the last: to the film, which focusing
// moves), the index of refraction behind it (0 for air) and its aperture's diameter.
struct LensInterface {
    double radius, thickness, eta, apertureDiameter;
};

// Rows of four numbers, '#' starting a comment (pbrt-v4 reads them with ReadFloatFile).
// Returns the interfaces, or a message saying what is wrong.
struct LensFile {
    std::vector<LensInterface> interfaces;
    std::string error;  // empty when read
};
LensFile parseLensFile(const std::string& text);

// The system's paraxial (first-order) focal length, from a ray parallel to the axis traced
// through every interface with the reduced-angle transfer matrices (Hecht, Optics, sec. 6.2):
// at an interface from index n to n', n'u' = nu - y (n' - n) / R; over a gap t in index n',
// y' = y + t u'. f = -1 / (n u) after the last interface for y = 1; nullopt if the system
// does not converge light (f not positive or not finite).
std::optional<double> paraxialFocalLength(const std::vector<LensInterface>& interfaces);

// The aperture stop's diameter (the row of radius 0), or nullopt if the file has none.
std::optional<double> apertureStopDiameter(const std::vector<LensInterface>& interfaces);

}  // namespace photon::pbrt
