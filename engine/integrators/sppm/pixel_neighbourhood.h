// The 3 x 3 pixels around a pixel, which the per-pixel learning (the lobe choice, the
// adaptive radius) reads together: one pixel's passes alone are too few to steer by.
#pragma once
#include <algorithm>
#include <cstddef>

namespace photon {

// Calls visit(j) for pixel `pixel` of a width x height image and each of its neighbours
// inside the image (four at a corner, nine inside), row by row.
template <class Visit>
void forNeighbourhood(size_t pixel, int width, int height, Visit&& visit) {
    const int x = static_cast<int>(pixel % static_cast<size_t>(width)), y = static_cast<int>(pixel / static_cast<size_t>(width));
    for (int yy = std::max(y - 1, 0); yy <= std::min(y + 1, height - 1); ++yy)
        for (int xx = std::max(x - 1, 0); xx <= std::min(x + 1, width - 1); ++xx)
            visit(static_cast<size_t>(yy) * static_cast<size_t>(width) + static_cast<size_t>(xx));
}

}  // namespace photon
