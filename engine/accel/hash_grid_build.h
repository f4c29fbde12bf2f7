// Template part of HashGrid::build: gathers centers and radii, then the counting sort.
#pragma once
#include <tbb/parallel_for.h>

namespace photon {

template <class CenterFn, class RadiusFn>
void HashGrid::build(size_t count, CenterFn center, RadiusFn radius) {
    std::vector<Vec3> centers(count);
    std::vector<float> radii(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        centers[i] = center(i);
        radii[i] = radius(i);
    });
    countAndFill(count, centers, radii);
}

}  // namespace photon
