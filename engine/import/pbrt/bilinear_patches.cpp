#include "import/pbrt/bilinear_patches.h"
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace photon::pbrt {
namespace {

Vec3 bilinear(Vec3 p00, Vec3 p10, Vec3 p01, Vec3 p11, float u, float v) {
    return (p00 * (1 - u) + p10 * u) * (1 - v) + (p01 * (1 - u) + p11 * u) * v;
}
Vec2 bilinear(Vec2 a, Vec2 b, Vec2 c, Vec2 d, float u, float v) {
    const Vec3 p = bilinear(Vec3(a.x, a.y, 0), Vec3(b.x, b.y, 0), Vec3(c.x, c.y, 0), Vec3(d.x, d.y, 0), u, v);
    return {p.x, p.y};
}

// Flat when p11 lies within 1e-5 of the patch's size of the plane through the other three.
bool flat(Vec3 p00, Vec3 p10, Vec3 p01, Vec3 p11) {
    const Vec3 n = cross(p10 - p00, p01 - p00);
    const float size = std::max({length(p10 - p00), length(p01 - p00), length(p11 - p00)});
    const float len = length(n);
    if (!(len > 0)) return true;  // degenerate: the triangles say what there is
    return std::abs(dot(p11 - p00, n / len)) <= 1e-5f * size;
}

}  // namespace

TriangleMesh bilinearPatches(TriangleMesh mesh, const std::vector<uint32_t>& indices, size_t maxTriangles) {
    mesh.indices.clear();
    const bool normals = !mesh.normals.empty(), uvs = !mesh.uvs.empty();
    for (size_t i = 0; i + 3 < indices.size(); i += 4) {
        const uint32_t c[4] = {indices[i], indices[i + 1], indices[i + 2], indices[i + 3]};
        const Vec3 p00 = mesh.positions[c[0]], p10 = mesh.positions[c[1]], p01 = mesh.positions[c[2]],
                   p11 = mesh.positions[c[3]];
        if (flat(p00, p10, p01, p11)) {
            mesh.indices.insert(mesh.indices.end(), {c[0], c[1], c[3], c[0], c[3], c[2]});
            continue;
        }
        constexpr int n = kCurvedPatchCells;
        if (mesh.triangleCount() + 2 * n * n > maxTriangles)
            throw std::length_error("its curved patches make more than " + std::to_string(maxTriangles) + " triangles");
        const uint32_t first = uint32_t(mesh.positions.size());
        for (int j = 0; j <= n; ++j)
            for (int k = 0; k <= n; ++k) {
                const float u = float(k) / n, v = float(j) / n;
                mesh.positions.push_back(bilinear(p00, p10, p01, p11, u, v));
                if (normals) {
                    const Vec3 s = bilinear(mesh.normals[c[0]], mesh.normals[c[1]], mesh.normals[c[2]], mesh.normals[c[3]], u, v);
                    mesh.normals.push_back(length(s) > 0 ? normalize(s) : s);
                }
                if (uvs) mesh.uvs.push_back(bilinear(mesh.uvs[c[0]], mesh.uvs[c[1]], mesh.uvs[c[2]], mesh.uvs[c[3]], u, v));
            }
        auto at = [&](int j, int k) { return first + uint32_t(j * (n + 1) + k); };
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                mesh.indices.insert(mesh.indices.end(),
                                    {at(j, k), at(j, k + 1), at(j + 1, k + 1), at(j, k), at(j + 1, k + 1), at(j + 1, k)});
    }
    return mesh;
}

}  // namespace photon::pbrt
