// A camera's lens system traced ray by ray, as pbrt-v4's RealisticCamera does (Pharr, Jakob &
// Humphreys, 4th ed., sec. 5.3): a film point, a point on the rear element, the ray refracted
// through every spherical interface and stopped by any aperture it misses. Its image shows
// the system's distortion, vignetting, aberrations and its depth of field as they are.
//
// Lens space: the film at z = 0, the lens toward +z (the scene), x right and y up as seen
// from behind the film, in metres. The film is pbrt-v4's: its diagonal over the image's
// shape, the image inverted by the lens (raster x = 0 at +x, y = 0 at -y on the film).
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "description/lens_interface.h"
#include <photon/vec.h>

namespace photon {

// The system's paraxial (first-order) focal length in the file's units, from a ray parallel
// to the axis traced through every interface with the reduced-angle transfer matrices (Hecht,
// Optics, sec. 6.2): at an interface from index n to n', n'u' = nu - y (n' - n) / R; over a
// gap t in index n', y' = y + t u'. f = -1 / (n u) after the last interface for y = 1;
// nullopt if the system does not converge light (f not positive or not finite).
std::optional<double> paraxialFocalLength(const std::vector<LensInterface>& interfaces);

// The aperture stop's diameter (the row of radius 0), or nullopt if the system has none.
std::optional<double> apertureStopDiameter(const std::vector<LensInterface>& interfaces);

// What is wrong with one interface, if anything: its thickness must be >= 0 and finite, its
// index 0 (air) or >= 1, its aperture > 0.
std::optional<std::string> lensInterfaceError(const LensInterface& s);

class LensSystem {
public:
    // `interfaces` in mm; the stop opened to `apertureDiameterMm` (clamped to its own, as
    // pbrt-v4; <= 0: its own); the film moved so that `focusDistance` (m, from the film) is
    // in focus by the thick-lens approximation (pbrt-v4's FocusThickLens); a film of
    // `filmDiagonalMm` over width x height pixels. Throws std::invalid_argument saying why
    // the system cannot be focused there. With `boundPupil`, the exit pupil's bounds are
    // found (boundExitPupil: 4M rays traced, about a second) and samples drawn within them.
    LensSystem(std::vector<LensInterface> interfaces, double apertureDiameterMm, double focusDistance,
               double filmDiagonalMm, int width, int height, bool boundPupil = false);

    // The ray for raster position (x, y) through a point of the rear element's plane drawn
    // with uLens, in lens space, with its weight: cos^4 theta A / z^2 of the film ray (theta
    // from the axis, A the area the point was drawn over, z the rear vertex's distance),
    // pbrt-v4's RealisticCamera weighting; nullopt where the system stops it. The point is
    // uniform over the rear element's disc, or with the pupil bound, over the box of the
    // plane through which rays from film points at that distance from the centre pass
    // (turned to the point's azimuth), so that fewer rays are stopped.
    struct Sample {
        Vec3 origin, direction;  // direction of unit length
        float weight;
    };
    std::optional<Sample> sample(float x, float y, Vec2 uLens) const;

    // The distance from the film to the rear interface, once focused (m).
    double filmDistance() const { return elements_.back().thickness; }
    // The effective focal length (m).
    double focalLength() const { return focalLength_; }
    double filmWidth() const { return filmWidth_; }
    double filmHeight() const { return filmHeight_; }

private:
    struct Element {
        double radius, thickness, eta, apertureRadius;  // metres; eta 1 for air
    };
    struct Ray3 {
        double o[3], d[3];
    };
    // Through the system from the film toward the scene (pbrt-v4's TraceLensesFromFilm),
    // and the other way; false where an aperture stops the ray or it reflects totally.
    bool traceFromFilm(Ray3 ray, Ray3* out) const;
    bool traceFromScene(Ray3 ray, Ray3* out) const;
    // The first-order principal plane and focal point, z in lens space, of the side a ray
    // parallel to the axis enters from (pbrt-v4's ComputeCardinalPoints).
    void cardinalPoints(const Ray3& in, const Ray3& out, double* pz, double* fz) const;
    double frontZ() const;
    // The box on the rear vertex's plane, in x and y, outside which no ray from a film point
    // on the +x axis at a distance in [r0, r1] passes (pbrt-v4's BoundExitPupil): rays to
    // 65,536 Halton points over a square 1.5 times the rear element's radius (a curved rear
    // face may pass rays aimed past its rim), grown by two of a 256 x 256 grid's spacings.
    struct Box {
        double x0, y0, x1, y1;
        double area() const { return (x1 - x0) * (y1 - y0); }
    };
    Box boundExitPupil(double r0, double r1) const;

    std::vector<Element> elements_;
    std::vector<Box> pupil_;  // by distance from the film's centre, 64 bins; empty: the rear disc
    double focalLength_ = 0, filmWidth_ = 0, filmHeight_ = 0;
    int width_ = 1, height_ = 1;
};

}  // namespace photon
