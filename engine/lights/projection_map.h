// Projection maps (Jensen 2001, "Realistic Image Synthesis Using Photon Mapping",
// sec. 5.1.3): a grid over a light's emission directions (point and spot lights) or over
// its emission disc (directional lights) in which the cells that can send light toward
// some object are marked. Photons then leave through marked cells only, so few of them
// are wasted on empty space around a small or distant scene.
#pragma once
#include <optional>
#include <vector>
#include "../scene/scene_description.h"
#include "light.h"

namespace photon {

struct BoundingSphere {
    Vec3 center;
    float radius = 0;
};

// One bounding sphere per shape (the sphere itself, or the sphere about a mesh's bounding box).
std::vector<BoundingSphere> shapeBoundingSpheres(const std::vector<ShapeDescription>& shapes);

class ProjectionMap {
public:
    // Nothing for lights without an EmissionGeometry of kind Point or Parallel.
    static std::optional<ProjectionMap> build(const Light& light, const std::vector<BoundingSphere>& objects);

    // A photon through a marked cell: uCell picks the cell in proportion to the power the
    // light sends through it, uWithin a uniform point (direction or disc position) in it.
    // The flux is the emitted density over that pdf, so summed over photons it estimates
    // the power through the marked cells: unbiased, as no unmarked cell reaches geometry.
    std::optional<PhotonEmission> emit(double uCell, Vec2 uWithin) const;

    size_t cellCount() const { return static_cast<size_t>(rows_) * cols_; }
    size_t markedCount() const { return marked_.size(); }
    // Share of the light's power that leaves through marked cells.
    double markedPowerFraction() const { return markedPowerFraction_; }

private:
    struct CellBounds {
        float lo0, hi0, lo1, hi1;  // Point: z = cos(theta) and phi; Parallel: x and y on the unit disc
    };
    CellBounds cellBounds(size_t cell) const;
    Vec3 pointDirection(float z, float phi) const;  // world direction from the light's frame
    bool reaches(size_t cell, const std::vector<BoundingSphere>& objects) const;
    double cellPower(size_t cell) const;  // average over channels, W

    EmissionGeometry geometry_;
    const Light* light_ = nullptr;
    int rows_ = 0, cols_ = 0;
    float cellMeasure_ = 0;        // solid angle (Point) or area (Parallel) of every cell
    std::vector<uint32_t> marked_;  // marked cells
    std::vector<double> cdf_;       // over marked_, by power (double: cells are many and small)
    double markedPowerFraction_ = 1;
};

}  // namespace photon
