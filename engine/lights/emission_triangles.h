// A mesh's triangles prepared for sampling points uniformly by area: everything a sample
// needs, per triangle and in one place, since photons are emitted millions of times a
// pass. Mesh area lights sample through it one point at a time; the photon walk's lanes
// read the same triangles eight points at a time (photon_emitter_lanes.cpp).
#pragma once
#include <algorithm>
#include <vector>
#include "math/frame.h"
#include "math/sampling.h"
#include "description/scene_description.h"

namespace photon {

class EmissionTriangles {
public:
    struct Triangle {
        Vec3 p0, e1, e2;             // p = p0 + b1 e1 + b2 e2
        Frame frame;                 // n faces the emitting side
        float cdfLow, inverseWidth;  // where the triangle's share of [0, 1) starts, 1 / its size
    };

    // `areas` per triangle, summing to `total`.
    EmissionTriangles(const ShapeDescription& shape, const std::vector<double>& areas, double total) {
        const TriangleMesh& m = shape.mesh;
        float sign = shape.flipNormals ? -1.0f : 1.0f;
        double sum = 0;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            TriangleMesh::Corners k = m.corners(t);
            // (A mesh without area has no power and is never picked; its shares stay finite.)
            float lo = total > 0 ? static_cast<float>(sum / total) : 0.0f;
            sum += areas[t];
            float hi = t + 1 == m.triangleCount() || !(total > 0) ? 1.0f : static_cast<float>(sum / total);
            triangles_.push_back({k.a, k.b - k.a, k.c - k.a, Frame::fromNormal(m.faceNormal(t) * sign), lo,
                                  1.0f / std::max(hi - lo, 1e-12f)});
            cdf_.push_back(hi);
        }
    }

    // The triangle whose share of [0, 1) holds u (in proportion to its area).
    const Triangle& triangleAt(float u) const { return triangles_[std::min(indexAt(u), triangles_.size() - 1)]; }

    // What is left of u within the triangle's share, rescaled to [0, 1): a fresh uniform
    // number for the point on it.
    template <class F>
    static F reuse(F u, F cdfLow, F inverseWidth) {
        F x = (u - cdfLow) * inverseWidth;
        x = select(x < 0.0f, broadcast<F>(0.0f), x);
        return select(x > 0.99999994f, broadcast<F>(0.99999994f), x);
    }

    // A point uniform by area: u.x picks the triangle and, reused, with u.y the point.
    const Triangle& samplePoint(Vec2 u, Vec3& p) const {
        Vec2 barycentric;
        size_t index;
        return samplePoint(u, p, barycentric, index);
    }
    // The same, also telling which triangle (its index in the mesh) and where on it, as
    // Embree's barycentrics (u, v) of the second and third vertex (TriangleMesh::uvAt).
    const Triangle& samplePoint(Vec2 u, Vec3& p, Vec2& barycentric, size_t& index) const {
        index = std::min(indexAt(u.x), triangles_.size() - 1);
        const Triangle& tri = triangles_[index];
        p = pointOn(tri, {reuse(u.x, tri.cdfLow, tri.inverseWidth), u.y}, barycentric);
        return tri;
    }
    // A point uniform on the triangle from u, and its barycentrics as samplePoint's.
    static Vec3 pointOn(const Triangle& tri, Vec2 u, Vec2& barycentric) {
        Vec2 b = sampleUniformTriangle(u);
        // Barycentric b.x on the first vertex, b.y on the second.
        barycentric = {b.y, 1.0f - b.x - b.y};
        return tri.p0 + tri.e1 * barycentric.x + tri.e2 * barycentric.y;
    }

    size_t size() const { return triangles_.size(); }
    const Triangle& operator[](size_t i) const { return triangles_[i]; }
    float cdfUpper(size_t i) const { return cdf_[i]; }
    // Meshes with at most this many triangles (a quad's two) are picked from in lanes by
    // comparisons and selects rather than by a lookup per lane.
    static constexpr size_t kFewTriangles = 4;

private:
    // A few triangles (a quad's two) are counted without branches: the binary search's
    // branch is a coin toss there, mispredicted half the time.
    size_t indexAt(float u) const {
        if (cdf_.size() > 16) return static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
        size_t below = 0;
        for (float c : cdf_) below += c <= u;
        return below;
    }

    std::vector<Triangle> triangles_;
    std::vector<float> cdf_;  // upper ends of the triangles' shares
};

}  // namespace photon
