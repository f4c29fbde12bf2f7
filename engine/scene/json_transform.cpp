// The "transform" of a shape: scale, then rotate, then translate; or a full matrix.
#include <cmath>
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

namespace {

Vec3 readScale(const JsonValue& value) {
    if (value.json().is_number()) {
        float s = value.number();
        if (s == 0) value.fail("must not be 0");
        return Vec3(s);
    }
    if (!value.json().is_array()) value.fail("must be a number or an array of 3 numbers");
    Vec3 s = value.vec3();
    for (int i = 0; i < 3; ++i)
        if (s[i] == 0) throw SceneError(elementPath(value.path(), i), "must not be 0");
    return s;
}

// 16 numbers, row-major, the last row 0 0 0 1 (affine only: no projective transforms).
Transform readMatrix(const JsonValue& value) {
    if (!value.json().is_array() || value.json().size() != 16) value.fail("must be an array of 16 numbers");
    auto e = value.elements();
    Transform t;
    for (int i = 0; i < 12; ++i) t.m[i] = e[i].number();
    for (int i = 12; i < 16; ++i)
        if (e[i].number() != (i == 15 ? 1.0f : 0.0f)) value.fail("the last row must be 0, 0, 0, 1");
    return t;
}

// A singular matrix flattens the shape and has no normal transform. The test is relative
// (determinant against the product of the row lengths) so it does not depend on units.
bool invertible(const Transform& t) {
    Vec3 r0{t.m[0], t.m[1], t.m[2]}, r1{t.m[4], t.m[5], t.m[6]}, r2{t.m[8], t.m[9], t.m[10]};
    double scale = double(length(r0)) * length(r1) * length(r2);
    double det = t.determinant();
    return std::isfinite(det) && std::isfinite(scale) && std::fabs(det) > 1e-9 * scale;
}

}  // namespace

Transform readOrientation(const JsonValue& value) {
    const Transform t = readMatrix(value);
    if (t.m[3] != 0 || t.m[7] != 0 || t.m[11] != 0) value.fail("an environment has no position: the translation must be 0");
    if (!t.orthonormal()) value.fail("must be a rotation or a mirror image (orthonormal rows): it scales or shears");
    return t;
}

Transform readRotation(const JsonValue& value) {
    JsonObject obj = value.object();
    Vec3 axis = obj.required("axis").direction();
    float angle = obj.required("angle").number();
    obj.finish();
    return Transform::rotate(axis, angle);
}

Transform readTransform(const JsonValue& value) {
    JsonObject obj = value.object();
    Transform t;
    if (auto matrix = obj.optional("matrix")) {
        if (obj.has("scale") || obj.has("rotate") || obj.has("translate"))
            value.fail("use either \"matrix\" or \"scale\"/\"rotate\"/\"translate\", not both");
        t = readMatrix(*matrix);
    } else {
        if (auto scale = obj.optional("scale")) t = Transform::scale(readScale(*scale));
        if (auto rotate = obj.optional("rotate")) t = readRotation(*rotate) * t;
        if (auto translate = obj.optional("translate")) t = Transform::translate(translate->vec3()) * t;
    }
    obj.finish();
    if (!invertible(t)) value.fail("must be invertible (it flattens the shape)");
    return t;
}

}  // namespace photon::scene_json
