// The part of a ball that lies on the inner side of up to two planes: what a volume
// photon estimate's ball holds of a medium that ends at a surface behind the point and
// at one ahead of it (SppmIntegrator::storeVolumePoint).
#pragma once
#include <limits>
#include <photon/vec.h>

namespace photon {

// A plane at distance `distance` from the ball's centre along the unit vector `outward`
// (from the centre toward the plane); what lies beyond it is cut away. Infinite: no plane.
struct CuttingPlane {
    Vec3 outward{0.0f};
    float distance = std::numeric_limits<float>::infinity();
};

// The volume of the ball of radius r beyond a plane at distance h from its centre, over
// the ball's volume: a cap of height a = r - h, pi a^2 (3r - a) / 3.
float capShare(float h, float r);

// The share of the ball of radius r about the origin on the inner side of both planes
// (each at a distance >= 0: the centre is inside): 1 - caps + the part both cut away,
// which is zero unless the planes meet inside the ball. That part is integrated over
// slices parallel to the first plane, each a disc less the segment beyond the second
// (Gauss-Legendre in the slice's polar angle; within 1e-4 of the ball's volume).
float ballShareInside(const CuttingPlane& a, const CuttingPlane& b, float r);

}  // namespace photon
