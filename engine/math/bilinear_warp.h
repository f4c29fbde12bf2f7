// Tables on [0,1]^2 that are bilinear between samples on a regular nx x ny grid and may
// depend on parameters: one grid (a slice) per combination of the parameters' tabulated
// values, linearly interpolated between the slices around a parameter point. A
// BilinearWarp2D is such a table taken as a density and sampled by inversion: the marginal
// density of y, then x given y, each piecewise linear with a quadratic CDF inverted in
// closed form. This is the warp in which Dupuy & Jakob 2018 ("An Adaptive Parameterization
// for Efficient Material Acquisition and Rendering", sec. 5) store measured BRDFs, so the
// tables of their files are used as they are (materials/measured.cpp).
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>
#include <photon/vec.h>

namespace photon {

// Where a parameter point falls among the slices: up to 2^3 slices and their weights.
struct SliceBlend {
    std::array<uint32_t, 8> slice{};
    std::array<float, 8> weight{};
    int count = 0;
};

// The parameters' axes: each an ascending list of the values its slices were tabulated at.
// The slices are stored with the last parameter varying fastest.
class SliceAxes {
public:
    SliceAxes() = default;
    // At most three axes, each with at least one value, ascending. Throws
    // std::invalid_argument otherwise.
    explicit SliceAxes(std::vector<std::vector<float>> axes);
    size_t slices() const { return slices_; }
    // The slices around `params` (one value per axis) and their linear weights; a value
    // outside an axis's range takes the nearest end's slice.
    SliceBlend blend(std::span<const float> params) const;

private:
    std::vector<std::vector<float>> axes_;
    size_t slices_ = 1;
};

// A table's value at `p` in the blend of slices: bilinear within each slice's nx x ny grid
// (x fastest; sample (i, j) at (i / (nx - 1), j / (ny - 1))). T is float or Color.
template <class T>
class BilinearTable {
public:
    BilinearTable() = default;
    // values: slices * ny * nx; nx, ny at least 2.
    BilinearTable(int nx, int ny, std::vector<T> values);
    T eval(Vec2 p, const SliceBlend& blend) const;
    int nx() const { return nx_; }
    int ny() const { return ny_; }

private:
    int nx_ = 0, ny_ = 0;
    std::vector<T> values_;
};

// The table of one slice and no parameters.
SliceBlend singleSlice();

class BilinearWarp2D {
public:
    BilinearWarp2D() = default;
    // values: slices * ny * nx, non-negative. Each slice is normalised to a density on
    // [0,1]^2; a slice that is zero everywhere is taken as uniform.
    BilinearWarp2D(int nx, int ny, std::vector<float> values);

    struct Warped {
        Vec2 p;     // the warped point
        float pdf;  // the density at it (with respect to area on [0,1]^2)
    };
    // Maps a uniform point of [0,1]^2 to one distributed as the blended density.
    Warped sample(Vec2 u, const SliceBlend& blend) const;
    // The inverse: the uniform point that sample() maps to p, and the density at p.
    Warped invert(Vec2 p, const SliceBlend& blend) const;
    float density(Vec2 p, const SliceBlend& blend) const;

private:
    // Per slice, in the grid's index units (x in [0, nx - 1], y in [0, ny - 1]): the values
    // divided by the slice's integral, each row's running integral in x, and the running
    // integral in y of the rows' integrals.
    int nx_ = 0, ny_ = 0;
    std::vector<float> values_, rowCdf_, marginalCdf_;
    float blended(const std::vector<float>& table, size_t sliceSize, size_t index, const SliceBlend& blend) const;
};

}  // namespace photon
