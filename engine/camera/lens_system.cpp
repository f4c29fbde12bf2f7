#include "camera/lens_system.h"
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tbb/parallel_for.h>
#include "math/sampling.h"

namespace photon {

std::optional<double> paraxialFocalLength(const std::vector<LensInterface>& interfaces) {
    double y = 1, nu = 0, n = 1;  // height, reduced angle n u, index before the interface
    for (size_t i = 0; i < interfaces.size(); ++i) {
        const LensInterface& s = interfaces[i];
        const double next = s.eta == 0 ? 1.0 : s.eta;
        if (s.radius != 0) nu -= y * (next - n) / s.radius;
        // The last row's thickness is the film's distance, which focusing sets.
        if (i + 1 < interfaces.size()) y += s.thickness * nu / next;
        n = next;
    }
    // The system's power is -n u for y = 1; its effective focal length 1 / power (the
    // distance behind the rear principal plane where it focuses when the film is in air).
    if (!(nu < 0) || !std::isfinite(nu)) return std::nullopt;
    return -1.0 / nu;
}

std::optional<double> apertureStopDiameter(const std::vector<LensInterface>& interfaces) {
    for (const LensInterface& s : interfaces)
        if (s.radius == 0) return s.apertureDiameter;
    return std::nullopt;
}

std::optional<std::string> lensInterfaceError(const LensInterface& s) {
    if (!(s.thickness >= 0) || !std::isfinite(s.thickness) || !std::isfinite(s.radius) || !(s.eta == 0 || s.eta >= 1) ||
        !std::isfinite(s.eta) || !(s.apertureDiameter > 0) || !std::isfinite(s.apertureDiameter))
        return "the thickness must be >= 0, the index 0 (air) or >= 1, the aperture > 0";
    return std::nullopt;
}

namespace {
// k's digits in `base` mirrored about the point: the van der Corput sequence.
double radicalInverse(uint32_t base, uint32_t k) {
    double inverse = 1.0 / base, factor = inverse, value = 0;
    for (; k > 0; k /= base, factor *= inverse) value += double(k % base) * factor;
    return value;
}

double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void normalize3(double v[3]) {
    const double l = std::sqrt(dot3(v, v));
    for (int k = 0; k < 3; ++k) v[k] /= l;
}

// Where the ray meets the sphere of `radius` about (0, 0, zCenter) on the side the lens
// uses, and the normal there facing back along the ray (pbrt-v4's IntersectSphericalElement).
bool intersectSphere(double radius, double zCenter, const double o[3], const double d[3], double* t, double n[3]) {
    const double oc[3] = {o[0], o[1], o[2] - zCenter};
    const double a = dot3(d, d), b = 2 * dot3(d, oc), c = dot3(oc, oc) - radius * radius;
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return false;
    const double root = std::sqrt(discriminant);
    // Numerically stable roots (Press et al., Numerical Recipes, sec. 5.6).
    const double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    const bool closer = (d[2] > 0) != (radius < 0);
    *t = closer ? t0 : t1;
    if (!(*t >= 0)) return false;
    for (int k = 0; k < 3; ++k) n[k] = oc[k] + *t * d[k];
    normalize3(n);
    if (dot3(n, d) > 0)
        for (int k = 0; k < 3; ++k) n[k] = -n[k];
    return true;
}

// Snell's law for the direction d arriving at a surface of normal n (facing back along d),
// from index etaI into etaT; false for total internal reflection.
bool refract(double d[3], const double n[3], double etaI, double etaT) {
    double wi[3] = {-d[0], -d[1], -d[2]};
    normalize3(wi);
    const double eta = etaT / etaI, cosI = dot3(n, wi);
    const double sin2T = std::max(0.0, 1 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1) return false;
    const double cosT = std::sqrt(1 - sin2T);
    for (int k = 0; k < 3; ++k) d[k] = -wi[k] / eta + (cosI / eta - cosT) * n[k];
    return true;
}
}  // namespace

LensSystem::LensSystem(std::vector<LensInterface> interfaces, double apertureDiameterMm, double focusDistance,
                       double filmDiagonalMm, int width, int height, bool boundPupil)
    : width_(width), height_(height) {
    if (interfaces.empty()) throw std::invalid_argument("the lens system has no interfaces");
    for (const LensInterface& s : interfaces) {
        double aperture = s.apertureDiameter;
        if (s.radius == 0 && apertureDiameterMm > 0) aperture = std::min(aperture, apertureDiameterMm);
        elements_.push_back({s.radius * 0.001, s.thickness * 0.001, s.eta == 0 ? 1.0 : s.eta, aperture * 0.0005});
    }
    const double aspect = double(height) / double(width), diagonal = filmDiagonalMm * 0.001;
    filmWidth_ = std::sqrt(diagonal * diagonal / (1 + aspect * aspect));
    filmHeight_ = aspect * filmWidth_;
    // The thick lens: principal planes and focal points of either side from rays parallel to
    // the axis a thousandth of the film's diagonal off it (pbrt-v4's
    // ComputeThickLensApproximation), then the film moved by delta so that the plane at
    // -focusDistance images onto it (pbrt-v4's FocusThickLens).
    const double x = 0.001 * diagonal;
    double pz[2], fz[2];
    Ray3 fromScene{{x, 0, frontZ() + 1}, {0, 0, -1}}, toFilm;
    if (!traceFromScene(fromScene, &toFilm))
        throw std::invalid_argument("a ray parallel to the axis does not pass through the lens system");
    cardinalPoints(fromScene, toFilm, &pz[0], &fz[0]);
    Ray3 fromFilm{{x, 0, filmDistance() - 1}, {0, 0, 1}}, toScene;
    if (!traceFromFilm(fromFilm, &toScene))
        throw std::invalid_argument("a ray parallel to the axis does not pass back through the lens system");
    cardinalPoints(fromFilm, toScene, &pz[1], &fz[1]);
    focalLength_ = fz[0] - pz[0];
    const double z = -focusDistance;
    const double c = (pz[1] - z - pz[0]) * (pz[1] - z - 4 * focalLength_ - pz[0]);
    if (!(c > 0) || !(focalLength_ > 0))
        throw std::invalid_argument("the lens system cannot focus at " + std::to_string(focusDistance) +
                                    " m: it is too near for its focal length of " +
                                    std::to_string(focalLength_ * 1000) + " mm");
    const double delta = 0.5 * (pz[1] - z + pz[0] - std::sqrt(c));
    elements_.back().thickness += delta;
    if (!(elements_.back().thickness > 0))
        throw std::invalid_argument("focusing the lens system would put the film inside it");
    if (!boundPupil) return;
    constexpr int kBins = 64;
    const double halfDiagonal = 0.5 * diagonal;
    pupil_.resize(kBins);
    tbb::parallel_for(0, kBins, [&](int i) {
        pupil_[size_t(i)] = boundExitPupil(halfDiagonal * i / kBins, halfDiagonal * (i + 1) / kBins);
    });
}

LensSystem::Box LensSystem::boundExitPupil(double r0, double r1) const {
    constexpr int kSide = 256, kSamples = kSide * kSide;
    const double reach = 1.5 * elements_.back().apertureRadius, z = filmDistance();
    Box box{1, 1, -1, -1};  // empty
    auto inside = [&](double x, double y) { return x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1; };
    for (int k = 0; k < kSamples; ++k) {
        // Film points spread over [r0, r1] in order, rear points over the square by the
        // Halton sequence (bases 2 and 3), unrelated to that order.
        const double film = r0 + (r1 - r0) * (k + 0.5) / kSamples;
        const double x = -reach + 2 * reach * radicalInverse(2, uint32_t(k)),
                     y = -reach + 2 * reach * radicalInverse(3, uint32_t(k));
        if (inside(x, y)) continue;
        Ray3 ray{{film, 0, 0}, {x - film, y, z}};
        normalize3(ray.d);
        Ray3 out;
        if (!traceFromFilm(ray, &out)) continue;
        if (box.x0 > box.x1) box = {x, y, x, y};
        box.x0 = std::min(box.x0, x), box.x1 = std::max(box.x1, x);
        box.y0 = std::min(box.y0, y), box.y1 = std::max(box.y1, y);
    }
    if (box.x0 > box.x1) return {-reach, -reach, reach, reach};  // nothing passed: the whole square
    const double grow = 2 * 2 * reach / kSide;
    return {box.x0 - grow, box.y0 - grow, box.x1 + grow, box.y1 + grow};
}

double LensSystem::frontZ() const {
    double z = 0;
    for (const Element& e : elements_) z += e.thickness;
    return z;
}

void LensSystem::cardinalPoints(const Ray3& in, const Ray3& out, double* pz, double* fz) const {
    const double tf = -out.o[0] / out.d[0];
    *fz = -(out.o[2] + tf * out.d[2]);
    const double tp = (in.o[0] - out.o[0]) / out.d[0];
    *pz = -(out.o[2] + tp * out.d[2]);
}

// In lens space the scene lies toward -z: each ray's z is negated on the way in and out.
bool LensSystem::traceFromFilm(Ray3 r, Ray3* out) const {
    r.o[2] = -r.o[2], r.d[2] = -r.d[2];
    double elementZ = 0;
    for (int i = int(elements_.size()) - 1; i >= 0; --i) {
        const Element& e = elements_[size_t(i)];
        elementZ -= e.thickness;
        double t, n[3];
        const bool stop = e.radius == 0;
        if (stop) {
            if (r.d[2] >= 0) return false;
            t = (elementZ - r.o[2]) / r.d[2];
        } else if (!intersectSphere(e.radius, elementZ + e.radius, r.o, r.d, &t, n)) {
            return false;
        }
        for (int k = 0; k < 3; ++k) r.o[k] += t * r.d[k];
        if (r.o[0] * r.o[0] + r.o[1] * r.o[1] > e.apertureRadius * e.apertureRadius) return false;
        if (!stop && !refract(r.d, n, e.eta, i > 0 ? elements_[size_t(i) - 1].eta : 1.0)) return false;
    }
    r.o[2] = -r.o[2], r.d[2] = -r.d[2];
    *out = r;
    return true;
}

bool LensSystem::traceFromScene(Ray3 r, Ray3* out) const {
    r.o[2] = -r.o[2], r.d[2] = -r.d[2];
    double elementZ = -frontZ();
    for (size_t i = 0; i < elements_.size(); ++i) {
        const Element& e = elements_[i];
        double t, n[3];
        const bool stop = e.radius == 0;
        if (stop) {
            t = (elementZ - r.o[2]) / r.d[2];
        } else if (!intersectSphere(e.radius, elementZ + e.radius, r.o, r.d, &t, n)) {
            return false;
        }
        if (!(t >= 0)) return false;
        for (int k = 0; k < 3; ++k) r.o[k] += t * r.d[k];
        if (r.o[0] * r.o[0] + r.o[1] * r.o[1] > e.apertureRadius * e.apertureRadius) return false;
        if (!stop && !refract(r.d, n, i == 0 ? 1.0 : elements_[i - 1].eta, e.eta)) return false;
        elementZ += e.thickness;
    }
    r.o[2] = -r.o[2], r.d[2] = -r.d[2];
    *out = r;
    return true;
}

std::optional<LensSystem::Sample> LensSystem::sample(float x, float y, Vec2 uLens) const {
    // The film point (pbrt-v4's: x mirrored, the lens turning the image the right way up).
    const double sx = double(x) / width_, sy = double(y) / height_;
    const double film[3] = {-(-0.5 * filmWidth_ + sx * filmWidth_), -0.5 * filmHeight_ + sy * filmHeight_, 0};
    // A point on the rear element's plane: uniform over its disc, or over the exit pupil's
    // box for the film point's distance from the centre, turned to its azimuth.
    const Element& rear = elements_.back();
    double rearPoint[3] = {0, 0, rear.thickness}, area;
    if (pupil_.empty()) {
        const Vec2 disc = sampleUniformDiskConcentric(uLens);
        rearPoint[0] = disc.x * rear.apertureRadius, rearPoint[1] = disc.y * rear.apertureRadius;
        area = 3.14159265358979323846 * rear.apertureRadius * rear.apertureRadius;
    } else {
        const double r = std::hypot(film[0], film[1]);
        const size_t bin = std::min(pupil_.size() - 1, size_t(r / std::hypot(filmWidth_, filmHeight_) * 2 * pupil_.size()));
        const Box& b = pupil_[bin];
        const double px = b.x0 + (b.x1 - b.x0) * uLens.x, py = b.y0 + (b.y1 - b.y0) * uLens.y;
        const double c = r > 0 ? film[0] / r : 1, s = r > 0 ? film[1] / r : 0;
        rearPoint[0] = c * px - s * py, rearPoint[1] = s * px + c * py;
        area = b.area();
    }
    Ray3 ray{{film[0], film[1], film[2]}, {rearPoint[0] - film[0], rearPoint[1] - film[1], rearPoint[2] - film[2]}};
    normalize3(ray.d);
    const double cosTheta = ray.d[2];
    Ray3 out;
    if (!traceFromFilm(ray, &out)) return std::nullopt;
    normalize3(out.d);
    const double weight = cosTheta * cosTheta * cosTheta * cosTheta * area / (rear.thickness * rear.thickness);
    return Sample{Vec3(float(out.o[0]), float(out.o[1]), float(out.o[2])),
                  Vec3(float(out.d[0]), float(out.d[1]), float(out.d[2])), float(weight)};
}

}  // namespace photon
