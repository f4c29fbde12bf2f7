#include "projection_map.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>

namespace photon {

namespace {

// Grid sizes: fine enough that the cells straddling an object's outline, which send
// some photons past it, are a small share of those that reach it. A point light's cells
// are equal in solid angle (uniform in cos(theta) and phi): 1.5e-4 sr on the full sphere.
constexpr int kPointRows = 256, kPointCols = 512;
constexpr int kParallelCells = 512;

float angleBetween(Vec3 a, Vec3 b) { return std::acos(std::clamp(dot(a, b), -1.0f, 1.0f)); }

}  // namespace

std::vector<BoundingSphere> shapeBoundingSpheres(const std::vector<ShapeDescription>& shapes) {
    std::vector<BoundingSphere> spheres;
    for (const ShapeDescription& s : shapes) {
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

std::optional<ProjectionMap> ProjectionMap::build(const Light& light, const std::vector<BoundingSphere>& objects) {
    ProjectionMap m;
    m.geometry_ = light.emissionGeometry();
    m.light_ = &light;
    if (m.geometry_.kind == EmissionGeometry::Kind::Point) {
        m.rows_ = kPointRows;
        m.cols_ = kPointCols;
        m.cellMeasure_ = (1.0f - m.geometry_.cosMax) / kPointRows * (2.0f * kPi / kPointCols);
    } else if (m.geometry_.kind == EmissionGeometry::Kind::Parallel) {
        m.rows_ = m.cols_ = kParallelCells;
        float side = 2.0f * m.geometry_.disc.radius / kParallelCells;
        m.cellMeasure_ = side * side;
    } else {
        return std::nullopt;
    }
    std::vector<uint8_t> reach(m.cellCount());
    std::vector<double> power(m.cellCount());
    tbb::parallel_for(size_t(0), m.cellCount(), [&](size_t c) {
        power[c] = m.cellPower(c);
        reach[c] = power[c] > 0 && m.reaches(c, objects);
    });
    double total = 0, sum = 0;
    for (size_t c = 0; c < m.cellCount(); ++c) {
        total += power[c];
        if (!reach[c]) continue;
        sum += power[c];
        m.marked_.push_back(static_cast<uint32_t>(c));
        m.cdf_.push_back(sum);
    }
    for (double& v : m.cdf_) v /= sum;
    if (!m.cdf_.empty()) m.cdf_.back() = 1.0;
    m.markedPowerFraction_ = total > 0 ? sum / total : 0.0;
    return m;
}

ProjectionMap::CellBounds ProjectionMap::cellBounds(size_t cell) const {
    int r = static_cast<int>(cell / cols_), c = static_cast<int>(cell % cols_);
    if (geometry_.kind == EmissionGeometry::Kind::Point) {
        float dz = (1.0f - geometry_.cosMax) / rows_, dphi = 2.0f * kPi / cols_;
        return {geometry_.cosMax + r * dz, geometry_.cosMax + (r + 1) * dz, c * dphi, (c + 1) * dphi};
    }
    float d = 2.0f / cols_;
    return {-1 + c * d, -1 + (c + 1) * d, -1 + r * d, -1 + (r + 1) * d};
}

Vec3 ProjectionMap::pointDirection(float z, float phi) const {
    z = std::clamp(z, -1.0f, 1.0f);
    float s = std::sqrt(std::max(0.0f, 1 - z * z));
    return geometry_.frame.toWorld({s * std::cos(phi), s * std::sin(phi), z});
}

// Conservative: a cell is marked if the cone about its centre direction that holds the
// whole cell (Point), or the disc about its centre that holds the whole square (Parallel),
// meets some object's bounding sphere.
bool ProjectionMap::reaches(size_t cell, const std::vector<BoundingSphere>& objects) const {
    CellBounds b = cellBounds(cell);
    constexpr float kMargin = 1e-4f;
    if (geometry_.kind == EmissionGeometry::Kind::Point) {
        Vec3 axis = pointDirection(0.5f * (b.lo0 + b.hi0), 0.5f * (b.lo1 + b.hi1));
        // The farthest point of a z-phi cell from its centre is a corner: its edges are
        // meridian arcs and latitude arcs symmetric about the centre.
        float halfAngle = 0;
        for (float z : {b.lo0, b.hi0})
            for (float phi : {b.lo1, b.hi1}) halfAngle = std::max(halfAngle, angleBetween(axis, pointDirection(z, phi)));
        for (const BoundingSphere& s : objects) {
            Vec3 v = s.center - geometry_.position;
            float d = length(v);
            if (d <= s.radius * (1 + kMargin) + kMargin) return true;  // the light is inside it
            float angularRadius = std::asin(std::min(1.0f, s.radius / d));
            if (angleBetween(axis, v / d) <= halfAngle + angularRadius + kMargin) return true;
        }
        return false;
    }
    const SceneSphere& disc = geometry_.disc;
    float cx = 0.5f * (b.lo0 + b.hi0), cy = 0.5f * (b.lo1 + b.hi1);
    float halfDiagonal = std::sqrt(2.0f) * 0.5f * (b.hi0 - b.lo0);
    for (const BoundingSphere& s : objects) {
        Vec3 q = s.center - disc.center;
        float px = dot(q, geometry_.frame.s) / disc.radius, py = dot(q, geometry_.frame.t) / disc.radius;
        if (std::hypot(cx - px, cy - py) <= s.radius / disc.radius + halfDiagonal + kMargin) return true;
    }
    return false;
}

// Power through a cell, by the midpoint rule on 2x2 points (exactness is not needed: it
// only sets the probability of the cell, and the flux divides by the same number). A
// floor keeps cells with a little power from being dropped.
double ProjectionMap::cellPower(size_t cell) const {
    if (geometry_.kind == EmissionGeometry::Kind::Parallel) {
        CellBounds b = cellBounds(cell);
        float halfDiagonal = std::sqrt(2.0f) * 0.5f * (b.hi0 - b.lo0);
        if (std::hypot(0.5f * (b.lo0 + b.hi0), 0.5f * (b.lo1 + b.hi1)) - halfDiagonal >= 1) return 0;  // off the disc
        return average(light_->emittedDensity({})) * static_cast<double>(cellMeasure_);
    }
    CellBounds b = cellBounds(cell);
    double sum = 0;
    for (float fz : {0.25f, 0.75f})
        for (float fphi : {0.25f, 0.75f})
            sum += average(light_->emittedDensity(
                pointDirection(b.lo0 + fz * (b.hi0 - b.lo0), b.lo1 + fphi * (b.hi1 - b.lo1))));
    double peak = average(light_->emittedDensity(geometry_.frame.n));
    return std::max(sum / 4, 1e-3 * peak) * static_cast<double>(cellMeasure_);
}

std::optional<PhotonEmission> ProjectionMap::emit(double uCell, Vec2 uWithin) const {
    if (marked_.empty()) return std::nullopt;
    size_t i = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), uCell) - cdf_.begin());
    i = std::min(i, marked_.size() - 1);
    double probability = cdf_[i] - (i == 0 ? 0.0 : cdf_[i - 1]);
    CellBounds b = cellBounds(marked_[i]);
    float a = b.lo0 + uWithin.x * (b.hi0 - b.lo0), c = b.lo1 + uWithin.y * (b.hi1 - b.lo1);
    // Uniform in the cell (by solid angle: z and phi are both uniform), pdf 1 / (P measure).
    float inversePdf = static_cast<float>(static_cast<double>(cellMeasure_) / probability);
    if (geometry_.kind == EmissionGeometry::Kind::Point) {
        Vec3 w = pointDirection(a, c);
        Color flux = light_->emittedDensity(w) * inversePdf;
        if (isBlack(flux)) return std::nullopt;
        return PhotonEmission{geometry_.position, w, flux, Vec3{}};
    }
    if (a * a + c * c > 1) return std::nullopt;  // the corner of an edge cell, off the disc
    const SceneSphere& disc = geometry_.disc;
    const Frame& f = geometry_.frame;
    Vec3 origin = disc.center + (-f.n + f.s * a + f.t * c) * disc.radius;
    return PhotonEmission{origin, f.n, light_->emittedDensity(f.n) * inversePdf, Vec3{}};
}

}  // namespace photon
