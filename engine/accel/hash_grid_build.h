// Template part of HashGrid::build: gathers centers and radii, then the counting sort.
#pragma once
#include <tbb/parallel_for.h>
#include <stdexcept>

namespace photon {

template <class CenterFn, class RadiusSquaredFn>
void HashGrid::build(size_t count, CenterFn center, RadiusSquaredFn radiusSquared) {
    if (count >= (size_t(1) << kSphereBits)) throw std::length_error("HashGrid: more than 2^28 spheres");
    std::vector<Vec3> centers(count);
    std::vector<float> radiiSquared(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        centers[i] = center(i);
        radiiSquared[i] = radiusSquared(i);
    });
    countAndFill(count, centers, radiiSquared);
}

}  // namespace photon
