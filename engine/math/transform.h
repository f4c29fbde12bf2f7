// Affine transforms for mesh instancing: a 3x4 row-major matrix.
#pragma once
#include <array>
#include <cmath>
#include <photon/vec.h>

namespace photon {

struct Transform {
    // Row-major 3x4: rows map (x, y, z, 1) to x', y', z'.
    std::array<float, 12> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

    static Transform scale(Vec3 s) { return {{s.x, 0, 0, 0, 0, s.y, 0, 0, 0, 0, s.z, 0}}; }
    static Transform translate(Vec3 t) { return {{1, 0, 0, t.x, 0, 1, 0, t.y, 0, 0, 1, t.z}}; }
    // Rotation by `degrees` about `axis` (Rodrigues' formula).
    static Transform rotate(Vec3 axis, float degrees) {
        Vec3 a = normalize(axis);
        float th = degrees * kPi / 180.0f, c = std::cos(th), s = std::sin(th), t = 1 - c;
        return {{t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y, 0,
                 t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x, 0,
                 t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c, 0}};
    }
    bool identity() const { return m == Transform().m; }
    // this * other: apply `other` first.
    Transform operator*(const Transform& o) const {
        Transform r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) {
                float v = m[i * 4 + 0] * o.m[0 * 4 + j] + m[i * 4 + 1] * o.m[1 * 4 + j] + m[i * 4 + 2] * o.m[2 * 4 + j];
                if (j == 3) v += m[i * 4 + 3];
                r.m[i * 4 + j] = v;
            }
        return r;
    }
    Vec3 point(Vec3 p) const {
        return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
    }
    Vec3 vector(Vec3 v) const {
        return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
                m[8] * v.x + m[9] * v.y + m[10] * v.z};
    }
    // Whether the linear part is a rotation or a reflection: orthonormal rows, within
    // `tolerance` (then inverseRotation is its inverse).
    bool orthonormal(float tolerance = 1e-3f) const {
        const Vec3 r0{m[0], m[1], m[2]}, r1{m[4], m[5], m[6]}, r2{m[8], m[9], m[10]};
        for (float d : {dot(r0, r0) - 1, dot(r1, r1) - 1, dot(r2, r2) - 1, dot(r0, r1), dot(r1, r2), dot(r0, r2)})
            if (!(std::abs(d) <= tolerance)) return false;
        return true;
    }
    // A rotation's (or reflection's) inverse applied to v: its transpose.
    Vec3 inverseRotation(Vec3 v) const {
        return {m[0] * v.x + m[4] * v.y + m[8] * v.z, m[1] * v.x + m[5] * v.y + m[9] * v.z,
                m[2] * v.x + m[6] * v.y + m[10] * v.z};
    }
    // Normals transform by the inverse transpose: the cofactor matrix has the same
    // direction and needs no inverse (the scale is lost to normalisation anyway).
    Vec3 normal(Vec3 n) const {
        Vec3 r0{m[0], m[1], m[2]}, r1{m[4], m[5], m[6]}, r2{m[8], m[9], m[10]};
        Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
        // Rows of the inverse transpose are c0, c1, c2 over the determinant; keep its sign.
        Vec3 r{dot(c0, n), dot(c1, n), dot(c2, n)};
        return normalize(dot(r0, c0) < 0 ? -r : r);
    }
    // The inverse of an invertible transform (the caller checks the determinant): the
    // cofactors over the determinant for the linear part, then the translation undone.
    Transform inverse() const {
        Vec3 r0{m[0], m[1], m[2]}, r1{m[4], m[5], m[6]}, r2{m[8], m[9], m[10]};
        Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
        const float inv = 1.0f / dot(r0, c0);
        // The inverse's columns are c0, c1, c2 over the determinant.
        Transform r{{c0.x * inv, c1.x * inv, c2.x * inv, 0, c0.y * inv, c1.y * inv, c2.y * inv, 0, c0.z * inv,
                     c1.z * inv, c2.z * inv, 0}};
        const Vec3 t = r.vector({m[3], m[7], m[11]});
        r.m[3] = -t.x, r.m[7] = -t.y, r.m[11] = -t.z;
        return r;
    }
    float determinant() const {
        Vec3 r0{m[0], m[1], m[2]}, r1{m[4], m[5], m[6]}, r2{m[8], m[9], m[10]};
        return dot(r0, cross(r1, r2));
    }
};

}  // namespace photon
