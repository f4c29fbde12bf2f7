#include "import/pbrt/loop_subdivision.h"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace photon::pbrt {

namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

// What one round (or the limit rule) needs of the mesh: each edge's faces' far corners, and
// each vertex's neighbours and whether it lies on a boundary (an edge with one face; an
// edge with more than two counts as a boundary too, so a non-manifold mesh stays whole).
struct Adjacency {
    struct Edge {
        uint32_t a, b;
        std::vector<uint32_t> opposite;
        bool boundary() const { return opposite.size() != 2; }
    };
    std::vector<Edge> edges;
    std::unordered_map<uint64_t, uint32_t> edgeOf;
    std::vector<std::vector<uint32_t>> neighbours, boundaryNeighbours;

    explicit Adjacency(const TriangleMesh& m) {
        const size_t n = m.positions.size();
        neighbours.resize(n);
        boundaryNeighbours.resize(n);
        for (size_t t = 0; t < m.indices.size(); t += 3)
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = m.indices[t + k], b = m.indices[t + (k + 1) % 3], c = m.indices[t + (k + 2) % 3];
                auto [it, added] = edgeOf.try_emplace(edgeKey(a, b), uint32_t(edges.size()));
                if (added) edges.push_back({a, b, {}});
                edges[it->second].opposite.push_back(c);
            }
        for (const Edge& e : edges) {
            neighbours[e.a].push_back(e.b);
            neighbours[e.b].push_back(e.a);
            if (e.boundary()) {
                boundaryNeighbours[e.a].push_back(e.b);
                boundaryNeighbours[e.b].push_back(e.a);
            }
        }
    }
    bool onBoundary(uint32_t v) const { return !boundaryNeighbours[v].empty(); }
};

Vec3 sum(const std::vector<Vec3>& p, const std::vector<uint32_t>& of) {
    Vec3 s(0.0f);
    for (uint32_t i : of) s += p[i];
    return s;
}

// Warren's beta for a vertex of valence n (pbrt's "beta").
float beta(size_t n) { return n == 3 ? 3.0f / 16.0f : 3.0f / (8.0f * float(n)); }

// The boundary rule for a vertex with its two boundary neighbours: (1 - 2w) v + w (b0 + b1);
// with another count of them (a corner of a non-manifold fan) the vertex stays where it is.
Vec3 boundaryRule(const std::vector<Vec3>& p, uint32_t v, const std::vector<uint32_t>& b, float w) {
    if (b.size() != 2) return p[v];
    return p[v] * (1 - 2 * w) + (p[b[0]] + p[b[1]]) * w;
}

TriangleMesh subdivideOnce(const TriangleMesh& m) {
    const Adjacency adj(m);
    const uint32_t n = uint32_t(m.positions.size());
    TriangleMesh out;
    out.positions.resize(n + adj.edges.size());
    // The old vertices, moved.
    for (uint32_t v = 0; v < n; ++v) {
        const auto& ring = adj.neighbours[v];
        if (adj.onBoundary(v)) {
            out.positions[v] = boundaryRule(m.positions, v, adj.boundaryNeighbours[v], 1.0f / 8.0f);
        } else if (!ring.empty()) {
            const float b = beta(ring.size());
            out.positions[v] = m.positions[v] * (1 - float(ring.size()) * b) + sum(m.positions, ring) * b;
        } else {
            out.positions[v] = m.positions[v];  // used by no triangle
        }
    }
    // A new vertex on every edge.
    for (size_t e = 0; e < adj.edges.size(); ++e) {
        const Adjacency::Edge& edge = adj.edges[e];
        const Vec3 a = m.positions[edge.a], b = m.positions[edge.b];
        out.positions[n + e] = edge.boundary() ? (a + b) * 0.5f
                                               : (a + b) * (3.0f / 8.0f) +
                                                     (m.positions[edge.opposite[0]] + m.positions[edge.opposite[1]]) * (1.0f / 8.0f);
    }
    // Each triangle in four, wound as it was.
    out.indices.reserve(m.indices.size() * 4);
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        const uint32_t ab = n + adj.edgeOf.at(edgeKey(a, b)), bc = n + adj.edgeOf.at(edgeKey(b, c)),
                       ca = n + adj.edgeOf.at(edgeKey(c, a));
        out.indices.insert(out.indices.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    return out;
}

}  // namespace

TriangleMesh loopSubdivide(const TriangleMesh& control, int levels, bool toLimit) {
    TriangleMesh m;
    m.positions = control.positions;
    m.indices = control.indices;
    for (int i = 0; i < levels; ++i) m = subdivideOnce(m);
    // To the limit surface: gamma = 1 / (n + 3 / (8 beta)) for an interior vertex, 1/5 along
    // a boundary.
    const Adjacency adj(m);
    std::vector<Vec3> limit(m.positions.size());
    for (uint32_t v = 0; v < limit.size() && toLimit; ++v) {
        const auto& ring = adj.neighbours[v];
        if (adj.onBoundary(v)) {
            limit[v] = boundaryRule(m.positions, v, adj.boundaryNeighbours[v], 1.0f / 5.0f);
        } else if (!ring.empty()) {
            const float nv = float(ring.size()), gamma = 1.0f / (nv + 3.0f / (8.0f * beta(ring.size())));
            limit[v] = m.positions[v] * (1 - nv * gamma) + sum(m.positions, ring) * gamma;
        } else {
            limit[v] = m.positions[v];
        }
    }
    if (toLimit) m.positions = std::move(limit);
    // Smooth normals: each face's area-weighted normal summed at its corners.
    m.normals.assign(m.positions.size(), Vec3(0.0f));
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const Vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
        const Vec3 face = cross(b - a, c - a);
        for (int k = 0; k < 3; ++k) m.normals[m.indices[t + k]] += face;
    }
    for (Vec3& nrm : m.normals) nrm = length(nrm) > 0 ? normalize(nrm) : Vec3(0, 0, 1);
    return m;
}

}  // namespace photon::pbrt
