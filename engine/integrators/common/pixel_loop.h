// The camera passes' loop: every pixel once, rows in parallel (oneTBB), each pixel with its
// own random stream keyed by its index, so what a pixel gets does not depend on threads.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <cstddef>
#include "math/rng.h"
#include "integrators/integrator.h"

namespace photon {

// Calls pixel(x, y, index, rng) for every pixel of rows [firstRow, endRow); once `cancel` is
// set, rows not yet begun are skipped.
template <class PixelFn>
void forEachPixelOfRows(int width, int firstRow, int endRow, const RngStream& stream, const CancelToken& cancel,
                        PixelFn pixel) {
    tbb::parallel_for(tbb::blocked_range<int>(firstRow, endRow), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            if (cancel.cancelled()) return;
            for (int x = 0; x < width; ++x) {
                size_t index = static_cast<size_t>(y) * width + x;
                Rng rng(stream, index);
                pixel(x, y, index, rng);
            }
        }
    });
}

// The same for every pixel of the image.
template <class PixelFn>
void forEachPixel(int width, int height, const RngStream& stream, const CancelToken& cancel, PixelFn pixel) {
    forEachPixelOfRows(width, 0, height, stream, cancel, pixel);
}

}  // namespace photon
