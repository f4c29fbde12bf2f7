// camera.filter as plain data: which pixel filter, and its parameters (pbrt-v4 sec. 8.8);
// camera/pixel_filter.h samples it.
#pragma once
#include <photon/vec.h>

namespace photon {

struct PixelFilterDescription {
    enum class Kind { Box, Triangle, Gaussian, Mitchell, Lanczos };
    Kind kind = Kind::Box;
    Vec2 radius{0.5f, 0.5f};  // in pixels, per axis; the filter is 0 beyond it
    float sigma = 0.5f;       // Gaussian: standard deviation in pixels
    float b = 1.0f / 3.0f, c = 1.0f / 3.0f;  // Mitchell-Netravali's B and C
    float tau = 3.0f;         // Lanczos: the sinc window's number of lobes
    // The radius each kind has unless one is given (pbrt-v4's defaults).
    static float defaultRadius(Kind kind) {
        switch (kind) {
            case Kind::Box: return 0.5f;
            case Kind::Gaussian: return 1.5f;
            case Kind::Lanczos: return 4.0f;
            case Kind::Triangle:
            case Kind::Mitchell: return 2.0f;
        }
        return 0.5f;
    }
};

}  // namespace photon
