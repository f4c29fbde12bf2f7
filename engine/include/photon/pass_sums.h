// Passes rendered on their own, to be added to a render elsewhere: what SPPM with the global
// radius schedule (render.radius_schedule "global") makes of a batch of passes. Each pass is
// an independent estimate of the image, so a render is the mean of its passes; a batch
// holds, per pixel, the sum of its passes' radiance in fixed point, so that batches from
// any machine add exactly, in any order, and N machines give the image one would.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace photon {

struct PassSums {
    // Fixed-point units per unit of radiance: 2^24, a resolution of 6e-8, and room in an
    // int64 for 10^6 passes of a radiance of 5 * 10^5.
    static constexpr double kScale = 16777216.0;

    int64_t first = 0;  // index of the batch's first pass (passes first .. first + count - 1)
    int64_t count = 0;  // passes summed
    int width = 0, height = 0;
    std::vector<int64_t> values;  // R, G, B per pixel, row by row, in units of 1 / kScale
    // The half of the passes with an odd index, for the error estimate: how many there are,
    // and per pixel their luminance (Rec. 709 of each pass's fixed-point R, G, B) summed.
    int64_t oddCount = 0;
    std::vector<int64_t> oddLuminance;

    // Adds another batch of the same image size; throws std::invalid_argument if the sizes
    // differ or a sum would overflow.
    void add(const PassSums& other);

    // A compact binary form (the values zlib-compressed), and back. decode throws
    // std::invalid_argument, naming what is wrong, on anything encode did not write.
    std::string encode() const;
    static PassSums decode(std::string_view bytes);
};

}  // namespace photon
