// A shape of "type": "curves": strands of control points from a HAIR file or inline, the
// basis that joins them and the profile swept along them (docs/scene-format.md#curves).
#include "scene/hair_file.h"
#include "scene/json_scene_parts.h"

namespace photon::scene_json {

namespace {

// Inline strands: [[x, y, z] or [x, y, z, width], ...] each; a point without a width takes
// `width` (which must then be given).
CurveSet readInlineStrands(const JsonValue& value, std::optional<float> width, const JsonObject& where) {
    CurveSet c;
    auto strands = value.elements();
    if (strands.empty()) value.fail("must contain at least one strand");
    for (const JsonValue& strand : strands) {
        c.strandStarts.push_back(uint32_t(c.points.size()));
        for (const JsonValue& point : strand.elements()) {
            auto e = point.elements();
            if (e.size() != 3 && e.size() != 4) point.fail("must be [x, y, z] or [x, y, z, width]");
            CurvePoint p;
            p.p = {e[0].number(), e[1].number(), e[2].number()};
            if (e.size() == 4) {
                p.radius = 0.5f * e[3].number(Range::nonNegative());
            } else {
                if (!width) where.fail("needs \"width\" for points given without one");
                p.radius = 0.5f * *width;
            }
            c.points.push_back(p);
            if (c.points.size() > kMaxCurvePoints) value.fail("more than the limit of " + std::to_string(kMaxCurvePoints) + " points");
        }
    }
    return c;
}

CurveSet readHairFileValue(const JsonValue& file, std::optional<float> width, LoadContext& ctx) {
    const std::filesystem::path path = resolveFile(file, ctx);
    try {
        // A file without thicknesses needs the scene's width; 0 stands for none here.
        if (const std::string* bytes = ctx.importedFile(file.string()))
            return readHairFile(std::string_view(*bytes), file.string(), width.value_or(0.0f));
        return readHairFile(path, width.value_or(0.0f));
    } catch (const std::exception& e) {
        failWithLibraryError(file, e, ctx);
    }
}

}  // namespace

CurveSet readCurves(JsonObject& obj, LoadContext& ctx) {
    std::optional<float> width;
    if (auto w = obj.optional("width")) width = w->number(Range::positive());
    const bool hasFile = obj.has("file"), hasStrands = obj.has("strands");
    if (hasFile == hasStrands) obj.fail("curves need exactly one of \"file\" or \"strands\"");
    CurveSet c = hasFile ? readHairFileValue(obj.required("file"), width, ctx)
                         : readInlineStrands(obj.required("strands"), width, obj);
    if (auto basis = obj.optional("basis"))
        c.basis = CurveBasis(basis->choice({"bezier", "bspline", "catmull-rom", "linear"}, "basis"));
    else
        c.basis = CurveBasis::Linear;
    if (auto profile = obj.optional("profile")) c.profile = CurveProfile(profile->choice({"round", "flat"}, "profile"));
    for (size_t k = 0; k < c.strandCount(); ++k) {
        const size_t n = c.strandSize(k);
        if (CurveSet::segmentsOf(c.basis, n) > 0) continue;
        const std::string need = c.basis == CurveBasis::Bezier ? "3k + 1 points (k >= 1)"
                                 : c.basis == CurveBasis::Linear ? "at least 2 points"
                                                                 : "at least 4 points";
        obj.fail("strand " + std::to_string(k) + " has " + std::to_string(n) + " points; a " +
                 (c.basis == CurveBasis::Bezier ? "Bezier" : c.basis == CurveBasis::Linear ? "linear" : "cubic") +
                 " strand needs " + need);
    }
    bool anyWidth = false;
    for (const CurvePoint& p : c.points) anyWidth = anyWidth || p.radius > 0;
    if (!anyWidth) obj.fail("every point has width 0 (give \"width\", or thicknesses in the file)");
    return c;
}

}  // namespace photon::scene_json
