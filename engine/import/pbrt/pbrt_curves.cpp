// pbrt-v4's "curve" shapes: each directive a strand (hair files hold one per hair), gathered
// into one photon "curves" shape per material, profile and object, whose control points are
// written as a HAIR file (scene/hair_file.h) of cubic Bezier strands in world space (or the
// object's frame). pbrt's B-splines and quadratic curves become Bezier segments exactly.
#include <cmath>
#include "import/pbrt/pbrt_builder.h"
#include "scene/hair_file.h"

namespace photon::pbrt {

namespace {

Vec3 lerp(Vec3 a, Vec3 b, float t) { return a * (1.0f - t) + b * t; }

// The cubic Bezier control points (3k + 1) of pbrt's curve of degree 2 or 3 under its basis:
// a uniform B-spline segment as Bezier (Farin, "Curves and Surfaces for CAGD", sec. 7.2: the
// cubic's Bezier points at 1/3 and 2/3 of its middle control leg, its ends at the averages
// (p0 + 4 p1 + p2) / 6); a quadratic raised to a cubic (sec. 5.1, degree elevation).
std::vector<Vec3> bezierPoints(const std::vector<Vec3>& P, bool bspline, int degree) {
    std::vector<Vec3> out;
    auto push = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        if (out.empty()) out.push_back(a);
        out.insert(out.end(), {b, c, d});
    };
    if (degree == 3 && !bspline) return P;
    if (degree == 3) {
        for (size_t i = 0; i + 3 < P.size(); ++i) {
            const Vec3 p0 = P[i], p1 = P[i + 1], p2 = P[i + 2], p3 = P[i + 3];
            push((p0 + p1 * 4 + p2) / 6, (p1 * 2 + p2) / 3, (p1 + p2 * 2) / 3, (p1 + p2 * 4 + p3) / 6);
        }
        return out;
    }
    const size_t step = bspline ? 1 : 2;
    for (size_t i = 0; i + 2 < P.size(); i += step) {
        Vec3 q0 = P[i], q1 = P[i + 1], q2 = P[i + 2];
        if (bspline) q0 = (q0 + q1) / 2, q2 = (q1 + q2) / 2;
        push(q0, lerp(q0, q1, 2.0f / 3), lerp(q2, q1, 2.0f / 3), q2);
    }
    return out;
}

}  // namespace

void SceneBuilder::addCurve(const Params& p, const Directive& d) {
    const std::string where = describe(d);
    const std::string basis = p.string("basis", "bezier");
    if (basis != "bezier" && basis != "bspline") fail(d.where, where + ": basis must be \"bezier\" or \"bspline\"");
    const int degree = int(p.number("degree", 3));
    if (degree != 2 && degree != 3) fail(d.where, where + ": degree must be 2 or 3");
    const std::vector<double> raw = p.numbers("P", {"point3", "point"});
    std::vector<Vec3> P;
    for (size_t i = 0; i + 2 < raw.size(); i += 3) P.push_back({float(raw[i]), float(raw[i + 1]), float(raw[i + 2])});
    const bool bspline = basis == "bspline";
    if (raw.size() % 3 != 0 || P.size() < size_t(degree) + 1 || (!bspline && (P.size() - 1) % degree != 0))
        fail(d.where, where + ": \"P\" must hold " +
                          (bspline ? "at least " + std::to_string(degree + 1) + " points"
                                   : std::to_string(degree) + "k + 1 points (k >= 1)"));
    std::string type = p.string("type", "flat");
    if (type == "ribbon") {
        unsupported(d, where + ": ribbons oriented by \"N\" are not supported", "rendered as flat ribbons facing each ray");
        type = "flat";
    }
    if (type != "flat" && type != "cylinder") fail(d.where, where + ": type must be \"flat\", \"cylinder\" or \"ribbon\"");
    p.find("splitdepth");  // pbrt's subdivision of the curve for its own intersection test
    p.find("N");
    const double width = p.number("width", 1);
    const double w0 = p.number("width0", width), w1 = p.number("width1", width);
    if (!(w0 >= 0 && w1 >= 0) || !(w0 + w1 > 0)) fail(d.where, where + ": widths must be >= 0 and not both 0");
    if (state_.areaLight) unsupported(d, where + ": curves cannot emit", "their emission left out");
    if (floatValue(p, "alpha")) warn(d.where, where + ": alpha is not applied to curves");
    if (!state_.insideMedium.empty() || !state_.outsideMedium.empty())
        if (state_.insideMedium != state_.outsideMedium) warn(d.where, where + ": curves bound no medium; MediumInterface ignored");

    const std::vector<Vec3> bezier = bezierPoints(P, bspline, degree);
    const std::string key = currentMaterial() + "\n" + type + "\n" + currentObject_.value_or("");
    PendingCurves& pending = pendingCurves_[key];
    if (pending.shape.is_null()) {
        pending.shape = {{"type", "curves"}, {"file", "curves/" + std::to_string(++curveCount_) + ".hair"},
                         {"basis", "bezier"}, {"profile", type == "cylinder" ? "round" : "flat"},
                         {"material", currentMaterial()}};
        pending.object = currentObject_;
    }
    CurveSet& c = pending.curves;
    if (c.points.size() + bezier.size() > kMaxCurvePoints)
        fail(d.where, where + ": the scene's curves pass photon's limit of " + std::to_string(kMaxCurvePoints) + " points");
    // The width runs linearly from width0 to width1 along the curve (pbrt-v4's Curve), which
    // the Bezier basis reproduces from widths linear in the control points' index.
    const float scale = std::cbrt(std::abs(state_.ctm.determinant()));
    c.strandStarts.push_back(uint32_t(c.points.size()));
    for (size_t i = 0; i < bezier.size(); ++i) {
        const float t = float(i) / float(bezier.size() - 1);
        const Vec3 q = state_.ctm.point(bezier[i]);
        if (!isFinite(q)) fail(d.where, where + ": \"P\" has a coordinate that is not finite");
        c.points.push_back({q, 0.5f * scale * float(w0 + (w1 - w0) * t)});
    }
}

void SceneBuilder::flushCurves(const std::optional<std::string>& object) {
    for (auto it = pendingCurves_.begin(); it != pendingCurves_.end();) {
        if (it->second.object != object) {
            ++it;
            continue;
        }
        const std::string file = it->second.shape["file"];
        out_.files[file] = hairFileBytes(it->second.curves);
        if (object)
            objects_[*object]["shapes"].push_back(std::move(it->second.shape));
        else
            shapes_.push_back(std::move(it->second.shape));
        it = pendingCurves_.erase(it);
    }
}

}  // namespace photon::pbrt
