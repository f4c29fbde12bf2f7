#include "import/pbrt/pbrt_quadrics.h"
#include <algorithm>
#include <cmath>

namespace photon::pbrt {

namespace {

constexpr double kPiD = 3.14159265358979323846;

// Segments around the z axis: 256 for a whole turn, the chord polygon's area then 0.01%
// short of the circle's, and proportionally fewer for part of one.
int segmentsAround(double phiMax) { return std::max(4, int(std::ceil(256 * phiMax / (2 * kPiD)))); }

// A (nu + 1) x (nv + 1) grid of a parametric surface over (u, v) in [0, 1]^2, `at(u, v, p, n)`
// giving the point and its unit normal; two triangles a cell, those of no area left out
// (a pole, a disk's centre). Wound to face the normals.
template <typename At>
TriangleMesh gridMesh(int nu, int nv, const At& at) {
    TriangleMesh m;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            const double u = double(i) / nu, v = double(j) / nv;
            Vec3 p, n;
            at(u, v, p, n);
            m.positions.push_back(p);
            m.normals.push_back(n);
            m.uvs.push_back({float(u), float(v)});
        }
    auto vertex = [&](int i, int j) { return uint32_t(j * (nu + 1) + i); };
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        const Vec3 e = cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
        if (!(length(e) > 0)) return;
        // Toward the normals (the three corners' sum: exact on these smooth surfaces).
        if (dot(e, m.normals[a] + m.normals[b] + m.normals[c]) < 0) std::swap(b, c);
        m.indices.insert(m.indices.end(), {a, b, c});
    };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            add(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
            add(vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
        }
    return m;
}

}  // namespace

TriangleMesh partialSphereMesh(double radius, double zMin, double zMax, double phiMaxDegrees) {
    // pbrt-v4's Sphere: theta from acos(z / r), u = phi / phiMax, v from the lower z to the upper.
    const double lo = std::clamp(std::min(zMin, zMax), -radius, radius), hi = std::clamp(std::max(zMin, zMax), -radius, radius);
    const double thetaLo = std::acos(std::clamp(lo / radius, -1.0, 1.0)), thetaHi = std::acos(std::clamp(hi / radius, -1.0, 1.0));
    const double phiMax = std::clamp(phiMaxDegrees, 0.0, 360.0) * kPiD / 180;
    // 128 rings from pole to pole, as the 256 segments around.
    const int rings = std::max(2, int(std::ceil(128 * (thetaLo - thetaHi) / kPiD)));
    return gridMesh(segmentsAround(phiMax), rings, [&](double u, double v, Vec3& p, Vec3& n) {
        const double phi = u * phiMax, theta = thetaLo + v * (thetaHi - thetaLo);
        n = Vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
        p = n * float(radius);
    });
}

TriangleMesh cylinderMesh(double radius, double zMin, double zMax, double phiMaxDegrees) {
    // pbrt-v4's Cylinder: u = phi / phiMax, v = (z - zMin) / (zMax - zMin); exact along z.
    const double phiMax = std::clamp(phiMaxDegrees, 0.0, 360.0) * kPiD / 180;
    const double z0 = std::min(zMin, zMax), z1 = std::max(zMin, zMax);
    return gridMesh(segmentsAround(phiMax), 1, [&](double u, double v, Vec3& p, Vec3& n) {
        const double phi = u * phiMax;
        n = Vec3(float(std::cos(phi)), float(std::sin(phi)), 0);
        p = Vec3(float(radius * std::cos(phi)), float(radius * std::sin(phi)), float(z0 + v * (z1 - z0)));
    });
}

TriangleMesh diskMesh(double height, double radius, double innerRadius, double phiMaxDegrees) {
    // pbrt-v4's Disk: u = phi / phiMax, v = (radius - rho) / (radius - innerRadius); the
    // annulus's sectors are flat, so one ring of cells is exact.
    const double phiMax = std::clamp(phiMaxDegrees, 0.0, 360.0) * kPiD / 180;
    return gridMesh(segmentsAround(phiMax), 1, [&](double u, double v, Vec3& p, Vec3& n) {
        const double phi = u * phiMax, rho = radius - v * (radius - innerRadius);
        n = Vec3(0, 0, 1);
        p = Vec3(float(rho * std::cos(phi)), float(rho * std::sin(phi)), float(height));
    });
}

}  // namespace photon::pbrt
