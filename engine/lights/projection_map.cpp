#include "lights/projection_map.h"
#include "math/plane_solid_angle.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>

namespace photon {

namespace {

// Grid sizes: fine enough that the cells straddling an object's outline, which send
// some photons past it, are a small share of those that reach it. A cube map keeps
// cells about square everywhere (a theta/phi grid has slivers at its poles): 256^2 cells
// a face are 3.2e-5 sr on average, 0.45 degrees across at a face's centre.
constexpr int kCubeSide = 256;
constexpr int kDiscSide = 512;

float angleBetween(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(a, b), -1.0f, 1.0f)); }


}  // namespace

std::vector<BoundingSphere> shapeBoundingSpheres(const std::vector<ShapeDescription>& shapes,
                                                 const std::function<bool(const ShapeDescription&)>& include) {
    std::vector<BoundingSphere> spheres;
    for (const ShapeDescription& s : shapes) {
        if (!include(s)) continue;
        if (s.kind == ShapeDescription::Kind::Sphere) {
            spheres.push_back({s.center, s.radius});
            continue;
        }
        if (s.mesh.positions.empty()) continue;
        Vec3 lo = s.mesh.positions[0], hi = lo;
        for (Vec3 p : s.mesh.positions) {
            lo = vmin(lo, p);
            hi = vmax(hi, p);
        }
        Vec3 c = (lo + hi) * 0.5f;
        float r2 = 0;
        for (Vec3 p : s.mesh.positions) r2 = std::max(r2, lengthSquared(p - c));
        spheres.push_back({c, std::sqrt(r2)});
    }
    return spheres;
}

BoundingSphere placed(BoundingSphere s, const Transform& t) {
    // The largest stretch squared is the largest eigenvalue of A^T A (A: t's linear part),
    // at most its largest absolute row sum (Gershgorin): s^2 for s times a rotation.
    Vec3 c[3] = {{t.m[0], t.m[4], t.m[8]}, {t.m[1], t.m[5], t.m[9]}, {t.m[2], t.m[6], t.m[10]}};
    float stretch2 = 0;
    for (int i = 0; i < 3; ++i)
        stretch2 = std::max(stretch2, std::abs(dot(c[i], c[0])) + std::abs(dot(c[i], c[1])) + std::abs(dot(c[i], c[2])));
    return {t.point(s.center), s.radius * std::sqrt(stretch2)};
}

std::optional<ProjectionMap> ProjectionMap::build(const Light& light, const std::vector<BoundingSphere>& objects) {
    ProjectionMap m;
    m.geometry_ = light.emissionGeometry();
    m.light_ = &light;
    if (m.geometry_.kind == EmissionGeometry::Kind::Point) {
        m.faces_ = 6;
        m.side_ = kCubeSide;
    } else if (m.geometry_.kind == EmissionGeometry::Kind::Parallel) {
        m.faces_ = 1;
        m.side_ = kDiscSide;
    } else {
        return std::nullopt;
    }
    const std::vector<BoundingSphere> seen = m.asSeenFromLight(objects);
    std::vector<uint8_t> reach(m.cellCount());
    std::vector<double> power(m.cellCount());
    tbb::parallel_for(size_t(0), m.cellCount(), [&](size_t i) {
        Cell c = m.cell(i);
        power[i] = m.cellPower(c);
        reach[i] = power[i] > 0 && m.reaches(c, seen);
    });
    double total = 0, sum = 0;
    for (size_t i = 0; i < m.cellCount(); ++i) {
        total += power[i];
        if (!reach[i]) continue;
        sum += power[i];
        m.marked_.push_back(static_cast<uint32_t>(i));
        m.cdf_.push_back(sum);
    }
    for (double& v : m.cdf_) v /= sum;
    if (!m.cdf_.empty()) m.cdf_.back() = 1.0;
    m.markedPowerFraction_ = total > 0 ? sum / total : 0.0;
    return m;
}

ProjectionMap::Cell ProjectionMap::cell(size_t index) const {
    int face = static_cast<int>(index / (static_cast<size_t>(side_) * side_));
    size_t inFace = index % (static_cast<size_t>(side_) * side_);
    int r = static_cast<int>(inFace / side_), c = static_cast<int>(inFace % side_);
    float d = 2.0f / side_;
    return {face, -1 + c * d, -1 + (c + 1) * d, -1 + r * d, -1 + (r + 1) * d};
}

// Faces in the light's frame: +z, -z, +x, -x, +y, -y, each with two tangent axes.
Vec3 ProjectionMap::faceDirection(int face, float u, float v) const {
    static const Vec3 axes[6][3] = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
                                    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                    {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {0, 0, 1}, {1, 0, 0}}};
    const Vec3* a = axes[face];
    return geometry_.frame.toWorld(normalize(a[0] + a[1] * u + a[2] * v));
}

float ProjectionMap::solidAngle(const Cell& c) const {
    return static_cast<float>(rectangleSolidAngle(c.u0, c.u1, c.v0, c.v1));
}

// A cube-map cell is a spherical quadrilateral with great-circle edges, so the point
// farthest from its centre is a corner.
std::pair<Vec3, float> ProjectionMap::boundingCone(const Cell& c) const {
    Vec3 axis = faceDirection(c.face, 0.5f * (c.u0 + c.u1), 0.5f * (c.v0 + c.v1));
    float halfAngle = 0;
    for (float u : {c.u0, c.u1})
        for (float v : {c.v0, c.v1}) halfAngle = std::max(halfAngle, angleBetween(axis, faceDirection(c.face, u, v)));
    return {axis, halfAngle};
}

std::vector<BoundingSphere> ProjectionMap::asSeenFromLight(const std::vector<BoundingSphere>& objects) const {
    std::vector<BoundingSphere> seen;
    for (const BoundingSphere& s : objects) {
        if (geometry_.kind == EmissionGeometry::Kind::Point) {
            Vec3 v = s.center - geometry_.position;
            float d = length(v);
            if (d <= s.radius) {
                seen.push_back({geometry_.frame.n, kPi});  // the light is inside it: every direction
                continue;
            }
            seen.push_back({v / d, std::asin(s.radius / d)});
        } else {
            const SceneSphere& disc = geometry_.disc;
            Vec3 q = s.center - disc.center;
            seen.push_back({{dot(q, geometry_.frame.s) / disc.radius, dot(q, geometry_.frame.t) / disc.radius, 0},
                            s.radius / disc.radius});
        }
    }
    return seen;
}

// Conservative: a cell is marked if the cone that holds it (Point), or the disc about its
// centre that holds the whole square (Parallel), meets some object's bounding sphere.
bool ProjectionMap::reaches(const Cell& c, const std::vector<BoundingSphere>& seen) const {
    constexpr float kMargin = 1e-4f;
    if (geometry_.kind == EmissionGeometry::Kind::Point) {
        auto [axis, halfAngle] = boundingCone(c);
        for (const BoundingSphere& s : seen)
            if (angleBetween(axis, s.center) <= halfAngle + s.radius + kMargin) return true;
        return false;
    }
    float cx = 0.5f * (c.u0 + c.u1), cy = 0.5f * (c.v0 + c.v1);
    float halfDiagonal = std::sqrt(2.0f) * 0.5f * (c.u1 - c.u0);
    for (const BoundingSphere& s : seen)
        if (std::hypot(cx - s.center.x, cy - s.center.y) <= s.radius + halfDiagonal + kMargin) return true;
    return false;
}

// Power through a cell, by the midpoint rule on 2x2 points for point kinds (exactness is
// not needed: it only sets the probability of the cell, and the flux divides by the same
// number). A floor keeps cells with a little power, inside a spot's cone, from being dropped.
double ProjectionMap::cellPower(const Cell& c) const {
    if (geometry_.kind == EmissionGeometry::Kind::Parallel) {
        float halfDiagonal = std::sqrt(2.0f) * 0.5f * (c.u1 - c.u0);
        if (std::hypot(0.5f * (c.u0 + c.u1), 0.5f * (c.v0 + c.v1)) - halfDiagonal >= 1) return 0;  // off the disc
        float side = (c.u1 - c.u0) * geometry_.disc.radius;
        return average(light_->emittedDensity({})) * static_cast<double>(side * side);
    }
    auto [axis, halfAngle] = boundingCone(c);
    float coneAngle = std::acos(std::clamp(geometry_.cosMax, -1.0f, 1.0f));
    if (angleBetween(axis, geometry_.frame.n) - halfAngle > coneAngle) return 0;  // outside a spot's cone
    double sum = 0;
    for (float fu : {0.25f, 0.75f})
        for (float fv : {0.25f, 0.75f})
            sum += average(
                light_->emittedDensity(faceDirection(c.face, c.u0 + fu * (c.u1 - c.u0), c.v0 + fv * (c.v1 - c.v0))));
    double peak = average(light_->emittedDensity(geometry_.frame.n));
    return std::max(sum / 4, 1e-3 * peak) * static_cast<double>(solidAngle(c));
}

std::optional<PhotonEmission> ProjectionMap::emit(double uCell, Vec2 uWithin) const {
    if (marked_.empty()) return std::nullopt;
    size_t i = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), uCell) - cdf_.begin());
    i = std::min(i, marked_.size() - 1);
    double probability = cdf_[i] - (i == 0 ? 0.0 : cdf_[i - 1]);
    Cell c = cell(marked_[i]);
    float u = c.u0 + uWithin.x * (c.u1 - c.u0), v = c.v0 + uWithin.y * (c.v1 - c.v0);
    // Uniform by area on the cell's square: density probability / area there.
    double areaPdf = probability / (static_cast<double>(c.u1 - c.u0) * (c.v1 - c.v0));
    if (geometry_.kind == EmissionGeometry::Kind::Point) {
        // By solid angle the density is the area density times dA/dw = (1 + u^2 + v^2)^(3/2).
        Vec3 w = faceDirection(c.face, u, v);
        double pdf = areaPdf * std::pow(1.0 + u * u + v * v, 1.5);
        Color flux = light_->emittedDensity(w) * static_cast<float>(1.0 / pdf);
        if (isBlack(flux)) return std::nullopt;
        return PhotonEmission{geometry_.position, w, flux, Vec3{}};
    }
    if (u * u + v * v > 1) return std::nullopt;  // the corner of an edge cell, off the disc
    const SceneSphere& disc = geometry_.disc;
    const Frame& f = geometry_.frame;
    Vec3 origin = disc.center + (-f.n + f.s * u + f.t * v) * disc.radius;
    double pdf = areaPdf / (static_cast<double>(disc.radius) * disc.radius);  // per unit of world area
    return PhotonEmission{origin, f.n, light_->emittedDensity(f.n) * static_cast<float>(1.0 / pdf), Vec3{}};
}

}  // namespace photon
