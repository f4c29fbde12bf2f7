// Projection maps (Jensen 2001, "Realistic Image Synthesis Using Photon Mapping",
// sec. 5.1.3): a grid over a light's emission directions (point and spot lights: a cube
// map in the light's frame) or over its emission disc (directional lights: a square grid)
// in which the cells that can send light toward some object are marked. Photons then
// leave through marked cells only, so few of them are wasted on empty space around a
// small or distant scene.
#pragma once
#include <functional>
#include <optional>
#include <vector>
#include "description/scene_description.h"
#include "lights/light.h"

namespace photon {

struct BoundingSphere {
    Vec3 center;
    float radius = 0;
};
// A sphere bounding `s` moved by `t`: its centre moved, its radius times a bound on t's
// largest stretch (exact for rotations with a uniform scale).
BoundingSphere placed(BoundingSphere s, const Transform& t);

// One bounding sphere per shape that `include` accepts (the sphere itself, or the sphere
// about a mesh's bounding box).
std::vector<BoundingSphere> shapeBoundingSpheres(const std::vector<ShapeDescription>& shapes,
                                                 const std::function<bool(const ShapeDescription&)>& include);

class ProjectionMap {
public:
    // Nothing for lights without an EmissionGeometry of kind Point or Parallel.
    static std::optional<ProjectionMap> build(const Light& light, const std::vector<BoundingSphere>& objects);

    // A photon through a marked cell: uCell picks the cell in proportion to the power the
    // light sends through it, uWithin a uniform point (direction or disc position) in it.
    // The flux is the emitted density over that pdf, so summed over photons it estimates
    // the power through the marked cells: unbiased, as no unmarked cell reaches geometry.
    std::optional<PhotonEmission> emit(double uCell, Vec2 uWithin) const;

    // Point kinds pick a direction (uWithin is a direction sample), parallel ones a position.
    bool emitsFromPoint() const { return geometry_.kind == EmissionGeometry::Kind::Point; }
    size_t cellCount() const { return static_cast<size_t>(faces_) * side_ * side_; }
    size_t markedCount() const { return marked_.size(); }
    // Share of the light's power that leaves through marked cells.
    double markedPowerFraction() const { return markedPowerFraction_; }

private:
    // A cell: a square [u0, u1] x [v0, v1] on a cube face (Point; the face at distance 1
    // along its axis) or on the unit disc's bounding square (Parallel, face 0).
    struct Cell {
        int face;
        float u0, u1, v0, v1;
    };
    Cell cell(size_t index) const;
    Vec3 faceDirection(int face, float u, float v) const;  // unit world direction (Point)
    float solidAngle(const Cell& c) const;
    // Centre direction of a Point cell and the half-angle of a cone about it that holds the cell.
    std::pair<Vec3, float> boundingCone(const Cell& c) const;
    // The objects as the light sees them, computed once per map: for Point, a unit
    // direction and an angular radius (pi if the light is inside); for Parallel, the
    // centre and radius of the footprint on the disc, in units of the disc's radius.
    std::vector<BoundingSphere> asSeenFromLight(const std::vector<BoundingSphere>& objects) const;
    bool reaches(const Cell& c, const std::vector<BoundingSphere>& seen) const;
    double cellPower(const Cell& c) const;  // average over channels, W

    EmissionGeometry geometry_;
    const Light* light_ = nullptr;
    int faces_ = 0, side_ = 0;      // faces (6 or 1) of side_ x side_ cells
    std::vector<uint32_t> marked_;  // marked cells
    std::vector<double> cdf_;       // over marked_, by power (double: cells are many and small)
    double markedPowerFraction_ = 1;
};

}  // namespace photon
