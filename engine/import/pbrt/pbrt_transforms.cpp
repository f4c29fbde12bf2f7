// pbrt's transformation directives on the current transformation matrix (CTM). Each one
// post-multiplies, as in pbrt-v4 (BasicSceneBuilder): `Translate` then `Scale` scales first.
#include <cmath>
#include <sstream>
#include "import/pbrt/pbrt_builder.h"

namespace photon::pbrt {

namespace {

// pbrt's 16 numbers are the matrix's columns one after another (pbrt-v4 transposes what it
// reads): the last four are the translation and the homogeneous 1 of an affine matrix.
Ctm fromColumns(const Directive& d) {
    const std::vector<double>& v = d.numbers;
    Ctm c;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) c.affine.m[row * 4 + col] = float(v[col * 4 + row]);
    for (int col = 0; col < 4; ++col) c.lastRow[col] = float(v[col * 4 + 3]);
    return c;
}

// a * b as 4x4 matrices (b applied first).
Ctm product(const Ctm& a, const Ctm& b) {
    auto at = [](const Ctm& c, int row, int col) { return row < 3 ? c.affine.m[row * 4 + col] : c.lastRow[col]; };
    Ctm r;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += double(at(a, row, k)) * at(b, k, col);
            (row < 3 ? r.affine.m[row * 4 + col] : r.lastRow[col]) = float(sum);
        }
    return r;
}

bool projective(const CtmLastRow& row) {
    return std::abs(row[0]) > 1e-6f || std::abs(row[1]) > 1e-6f || std::abs(row[2]) > 1e-6f ||
           std::abs(row[3] - 1) > 1e-6f;
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
    if (n == "Identity") return setCtm({});
    if (n == "Translate") t = Transform::translate({float(v[0]), float(v[1]), float(v[2])});
    if (n == "Scale") t = Transform::scale({float(v[0]), float(v[1]), float(v[2])});
    if (n == "Rotate") {
        const Vec3 axis{float(v[1]), float(v[2]), float(v[3])};
        if (!(length(axis) > 0)) fail(d.where, "Rotate: the axis is zero");
        t = Transform::rotate(axis, float(v[0]));
    }
    if (n == "LookAt") t = lookAt(d);
    if (n == "Transform") return setCtm(fromColumns(d));
    if (n == "ConcatTransform") return setCtm(product(ctm(), fromColumns(d)));
    if (n == "CoordinateSystem") {
        coordinateSystems_[d.strings.at(0)] = ctm();
        return;
    }
    if (n == "CoordSysTransform") {
        auto it = coordinateSystems_.find(d.strings.at(0));
        if (it == coordinateSystems_.end()) {
            warn(d.where, "CoordSysTransform \"" + d.strings.at(0) + "\": no such coordinate system; ignored");
            return;
        }
        return setCtm(it->second);
    }
    if (projective(state_.ctmLastRow))
        setCtm(product(ctm(), {t, kAffineLastRow}));
    else
        state_.ctm = state_.ctm * t;
}

const Transform& SceneBuilder::pointCtm(const Directive& d) const {
    const CtmLastRow& r = state_.ctmLastRow;
    if (projective(r)) {
        std::ostringstream row;
        row << r[0] << ' ' << r[1] << ' ' << r[2] << ' ' << r[3];
        fail(d.where, describe(d) + ": the transform is projective (its last row is " + row.str() +
                          "), which photon applies to directions only (infinite and distant lights)");
    }
    return state_.ctm;
}

}  // namespace photon::pbrt
