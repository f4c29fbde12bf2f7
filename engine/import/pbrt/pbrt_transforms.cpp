// pbrt's transformation directives on the current transformation matrix (CTM). Each one
// post-multiplies, as in pbrt-v4 (BasicSceneBuilder): `Translate` then `Scale` scales first.
#include <cmath>
#include "import/pbrt/pbrt_builder.h"

namespace photon::pbrt {

namespace {

// pbrt's 16 numbers are the matrix's columns one after another (pbrt-v4 transposes what it
// reads): the last four are the translation and the homogeneous 1.
Transform fromColumns(const Directive& d) {
    const std::vector<double>& v = d.numbers;
    if (std::abs(v[3]) > 1e-6 || std::abs(v[7]) > 1e-6 || std::abs(v[11]) > 1e-6 || std::abs(v[15] - 1) > 1e-6)
        fail(d.where, d.name + ": a projective matrix (its last row is not 0 0 0 1) is not supported");
    Transform t;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) t.m[row * 4 + col] = float(v[col * 4 + row]);
    return t;
}

// pbrt-v4's LookAt: the camera-from-world transform of a camera at `pos` looking at `look`,
// its x axis up x direction (pbrt's left-handed camera space: x right, y up, z forward).
Transform lookAt(const Directive& d) {
    const std::vector<double>& v = d.numbers;
    const Vec3 pos{float(v[0]), float(v[1]), float(v[2])}, look{float(v[3]), float(v[4]), float(v[5])},
        up{float(v[6]), float(v[7]), float(v[8])};
    if (!(length(look - pos) > 0)) fail(d.where, "LookAt: the eye and the point looked at are the same");
    const Vec3 dir = normalize(look - pos);
    if (!(length(cross(normalize(up), dir)) > 1e-6f)) fail(d.where, "LookAt: the up vector is parallel to the view");
    const Vec3 right = normalize(cross(normalize(up), dir)), newUp = cross(dir, right);
    // World from camera has the columns right, newUp, dir, pos; its inverse is wanted.
    Transform worldFromCamera{{right.x, newUp.x, dir.x, pos.x, right.y, newUp.y, dir.y, pos.y, right.z, newUp.z,
                               dir.z, pos.z}};
    return worldFromCamera.inverse();
}

}  // namespace

void SceneBuilder::transformDirective(const Directive& d) {
    const std::string& n = d.name;
    const std::vector<double>& v = d.numbers;
    Transform t;
    if (n == "Identity") {
        state_.ctm = Transform();
        return;
    }
    if (n == "Translate") t = Transform::translate({float(v[0]), float(v[1]), float(v[2])});
    if (n == "Scale") t = Transform::scale({float(v[0]), float(v[1]), float(v[2])});
    if (n == "Rotate") {
        const Vec3 axis{float(v[1]), float(v[2]), float(v[3])};
        if (!(length(axis) > 0)) fail(d.where, "Rotate: the axis is zero");
        t = Transform::rotate(axis, float(v[0]));
    }
    if (n == "LookAt") t = lookAt(d);
    if (n == "Transform") {
        state_.ctm = fromColumns(d);
        return;
    }
    if (n == "ConcatTransform") t = fromColumns(d);
    if (n == "CoordinateSystem") {
        coordinateSystems_[d.strings.at(0)] = state_.ctm;
        return;
    }
    if (n == "CoordSysTransform") {
        auto it = coordinateSystems_.find(d.strings.at(0));
        if (it == coordinateSystems_.end()) {
            warn(d.where, "CoordSysTransform \"" + d.strings.at(0) + "\": no such coordinate system; ignored");
            return;
        }
        state_.ctm = it->second;
        return;
    }
    state_.ctm = state_.ctm * t;
}

}  // namespace photon::pbrt
