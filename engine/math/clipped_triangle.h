// The part of a triangle on one side of a plane, for sampling an area light only where a
// surface can receive its light: a triangle cut by the plane through the receiving point
// keeps a triangle or a quad (Sutherland & Hodgman 1974, one plane), and points uniform by
// area on that part never fall behind the receiver, where half the samples of a light
// standing on a surface's horizon used to (Bitterli's coffee maker: 33-46% of the light
// samples on its body, tests/test_area_light_horizon.cpp).
#pragma once
#include <cmath>
#include "math/sampling.h"

namespace photon {

struct ClippedTriangle {
    Vec3 corner[4];  // a convex polygon, in the triangle's order
    int corners = 0;
    bool whole = false;  // every corner above: the triangle itself
    float area = 0;
    float fanArea0 = 0;  // of the fan's first triangle (corners 0, 1, 2); the rest is (0, 2, 3)

    // A point uniform by area on the polygon: u.x picks the fan's triangle and, rescaled, with
    // u.y the point on it.
    Vec3 pointAt(Vec2 u) const {
        const float x = u.x * area;
        const bool first = corners == 3 || x < fanArea0;
        const Vec3 a = corner[0], b = first ? corner[1] : corner[2], c = first ? corner[2] : corner[3];
        const float share = first ? fanArea0 : area - fanArea0;
        const float ux = first ? x : x - fanArea0;
        const Vec2 w = sampleUniformTriangle({std::min(share > 0 ? ux / share : 0.0f, 0.99999994f), u.y});
        return a * (1.0f - w.x - w.y) + b * w.x + c * w.y;
    }
};

// The part of (a, b, c) strictly above the plane through o with normal n (dot(x - o, n) > 0).
inline ClippedTriangle clipTriangleAbove(Vec3 a, Vec3 b, Vec3 c, Vec3 o, Vec3 n) {
    const Vec3 v[3] = {a, b, c};
    const float h[3] = {dot(a - o, n), dot(b - o, n), dot(c - o, n)};
    ClippedTriangle t;
    for (int i = 0; i < 3; ++i) {
        const int j = i == 2 ? 0 : i + 1;
        if (h[i] > 0) t.corner[t.corners++] = v[i];
        if ((h[i] > 0) != (h[j] > 0)) t.corner[t.corners++] = v[i] + (v[j] - v[i]) * (h[i] / (h[i] - h[j]));
    }
    if (t.corners < 3) return ClippedTriangle{};
    t.whole = h[0] > 0 && h[1] > 0 && h[2] > 0;
    t.fanArea0 = 0.5f * length(cross(t.corner[1] - t.corner[0], t.corner[2] - t.corner[0]));
    t.area = t.fanArea0;
    if (t.corners == 4) t.area += 0.5f * length(cross(t.corner[2] - t.corner[0], t.corner[3] - t.corner[0]));
    return t;
}

}  // namespace photon
