#include "description/shape_transform.h"
#include <cmath>
#include <utility>

namespace photon {

std::optional<float> uniformScale(const Transform& t) {
    // Columns of the linear part: images of the axes. A rotation times s maps them to
    // mutually orthogonal vectors of length |s|.
    Vec3 c[3] = {{t.m[0], t.m[4], t.m[8]}, {t.m[1], t.m[5], t.m[9]}, {t.m[2], t.m[6], t.m[10]}};
    float s = length(c[0]);
    const float tol = 1e-4f;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(length(c[i]) - s) > tol * s) return std::nullopt;
        if (std::fabs(dot(c[i], c[(i + 1) % 3])) > tol * s * s) return std::nullopt;
    }
    return s;
}

void applyTransform(const Transform& t, TriangleMesh& mesh) {
    for (Vec3& p : mesh.positions) p = t.point(p);
    for (Vec3& n : mesh.normals) n = t.normal(n);
    if (t.determinant() < 0)
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

// Radii scale by the cube root of the volume's scale: exact under uniform scale, a mean
// under others (a tube stays round).
void applyTransform(const Transform& t, CurveSet& curves) {
    const float radiusScale = std::cbrt(std::abs(t.determinant()));
    for (CurvePoint& c : curves.points) {
        c.p = t.point(c.p);
        c.radius *= radiusScale;
    }
}

bool transformShape(const Transform& t, ShapeDescription& shape) {
    if (shape.kind == ShapeDescription::Kind::Curves) {
        applyTransform(t, shape.curves);
        return true;
    }
    if (shape.kind == ShapeDescription::Kind::Mesh) {
        applyTransform(t, shape.mesh);
        return true;
    }
    std::optional<float> s = uniformScale(t);
    if (!s) return false;
    shape.center = t.point(shape.center);
    shape.radius *= *s;
    return true;
}

}  // namespace photon
