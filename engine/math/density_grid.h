// A density that varies in space: samples at the centres of a box's cells, trilinearly
// interpolated between them, toward the box's faces as if zeros lay beyond (half the
// outermost samples' value on the faces), and zero outside the box (pbrt-v4's SampledGrid
// in the bounds of its "uniformgrid" medium). Along a straight line the density inside
// one lattice cell is a product of three linear functions, a cubic in the distance, so its
// integral over the part of the line in the cell is exact by Simpson's rule: the optical
// depth of a segment is computed exactly (no ray marching step, no random numbers), cell by
// cell along the line (Amanatides & Woo 1987), and so is the distance at which it reaches a
// given depth. Free-flight sampling then needs one number a flight, as in a homogeneous
// medium, with no null collisions and no noise from estimated transmittance.
#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>
#include "math/transform.h"

namespace photon {

class DensityGrid {
public:
    // nx * ny * nz samples, x fastest, then y, then z (pbrt-v4's order); latticeFromWorld
    // takes a world point to lattice coordinates, where sample (i, j, k) sits at (i, j, k).
    DensityGrid(int nx, int ny, int nz, std::vector<float> values, const Transform& latticeFromWorld);
    // Samples held elsewhere (a sparse grid read from a file, scene/nanovdb_density.h), at
    // lattice points (i, j, k) in [0, n); `maxValue` bounds them.
    class Samples {
    public:
        virtual ~Samples() = default;
        // The samples at the corners (i, j, k) + (x, y, z), corner x + 2 y + 4 z, zero
        // outside [0, n): a cell's eight in one call, which a tree reads through one cached
        // path to its leaf.
        virtual void corners(int i, int j, int k, const int n[3], float c[8]) const = 0;
    };
    DensityGrid(int nx, int ny, int nz, std::shared_ptr<const Samples> samples, float maxValue,
                const Transform& latticeFromWorld);
    // The lattice coordinates of a point in the box [p0, p1] that the samples fill, each at
    // the centre of its cell of the box cut nx * ny * nz times (pbrt-v4's SampledGrid):
    // n (p - p0) / (p1 - p0) - 1/2.
    static Transform latticeFromBox(int nx, int ny, int nz, Vec3 p0, Vec3 p1);

    // The density at world point p.
    float at(Vec3 p) const;
    // The integral of the density along o + t d over t in [0, length] (d need not be of unit
    // length: t is in its units).
    double integral(Vec3 o, Vec3 d, float length) const;
    // Where along the same segment the integral from 0 reaches `depth` > 0: t, and depth;
    // if it stays below it, t infinite and the whole segment's integral.
    struct Reach {
        float t;
        double depth;
    };
    Reach reach(Vec3 o, Vec3 d, float length, double depth) const;

    // The largest of the samples at the corners of lattice cell (i, j, k) (0 outside
    // [0, n)): a bound on the density within the cell.
    float cellMax(int i, int j, int k) const {
        float c[8];
        corners(i, j, k, c);
        return *std::max_element(c, c + 8);
    }
    const Transform& latticeFromWorld() const { return latticeFromWorld_; }

    int nx() const { return n_[0]; }
    int ny() const { return n_[1]; }
    int nz() const { return n_[2]; }
    float maxValue() const { return max_; }

private:
    // The samples at the corners of the cell (i, j, k) (Samples::corners).
    void corners(int i, int j, int k, float c[8]) const;
    // Calls visit(t0, t1, cell) for each lattice cell the line o + t d crosses for t in
    // [0, length], in order, until it returns false; `cell` evaluates the density at any t.
    template <class Visit>
    void walk(Vec3 o, Vec3 d, float length, Visit&& visit) const;

    int n_[3];
    std::vector<float> values_;
    std::shared_ptr<const Samples> samples_;  // instead of values_
    Transform latticeFromWorld_;
    float max_ = 0;
};

}  // namespace photon
