// Curves in the scene: Embree's curve geometry over the shape's own control points, the
// hit record of a curve, and the filter that keeps a ray from hitting the fibre it leaves.
#include <algorithm>
#include <cmath>
#include "math/frame.h"
#include "math/ray.h"
#include "scene/scene.h"

namespace photon {
namespace {

RTCGeometryType curveType(const CurveSet& c) {
    const bool round = c.profile == CurveProfile::Round;
    switch (c.basis) {
        case CurveBasis::Bezier: return round ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE : RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE;
        case CurveBasis::BSpline:
            return round ? RTC_GEOMETRY_TYPE_ROUND_BSPLINE_CURVE : RTC_GEOMETRY_TYPE_FLAT_BSPLINE_CURVE;
        case CurveBasis::CatmullRom:
            return round ? RTC_GEOMETRY_TYPE_ROUND_CATMULL_ROM_CURVE : RTC_GEOMETRY_TYPE_FLAT_CATMULL_ROM_CURVE;
        case CurveBasis::Linear: break;
    }
    return round ? RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE : RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE;
}

// A ray leaving a fibre starts on (or, for a ribbon, within) the fibre's own width, and
// Embree would find the fibre again: the far wall of a tube, or the ribbon turned to face
// the new ray. A fibre's scattering (the hair model) already includes the light's way
// through it, so a hit on a curve is ignored when the ray's origin lies within the curve's
// radius of its centre line there (1% and the ray offset of math/ray.h to spare), measured
// across the line's tangent and no further than kAlongRadii radii along it: a ray that enters
// a tube at a glancing angle leaves it that far along (2 r tan(theta), 64 r at 88 degrees).
// pbrt-v4 moves the origin of such rays by the curve's width instead (Curve::Intersect's
// pError), which also steps over a touching fibre.
constexpr float kAlongRadii = 64;

bool startsInside(const CurveSample& c, Vec3 origin) {
    const Vec3 offset = origin - c.center;
    const float len2 = lengthSquared(c.dpdu);
    const float along = len2 > 0 ? dot(offset, c.dpdu) / std::sqrt(len2) : 0.0f;
    const float across2 = std::max(0.0f, lengthSquared(offset) - along * along);
    const float reach = 1.01f * c.radius + rayOffsetDistance(origin.x, origin.y, origin.z);
    return across2 <= reach * reach && std::abs(along) <= kAlongRadii * c.radius;
}

}  // namespace

// One filter for intersect and occluded queries, one ray or a packet's lanes.
void Scene::curveFilter(const RTCFilterFunctionNArguments* args) {
    const auto& g = *static_cast<const CurveGeometry*>(args->geometryUserPtr);
    const unsigned n = args->N;
    RTCRayN* ray = args->ray;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        const uint32_t first = g.segments.firstPoint[RTCHitN_primID(args->hit, n, i)];
        const CurveSample c = evaluateCurve(g.curves->basis, &g.curves->points[first], RTCHitN_u(args->hit, n, i));
        const Vec3 origin(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
        if (startsInside(c, origin)) args->valid[i] = 0;
    }
}

// The control points are Embree's vertex buffer as they are (CurvePoint is its float4
// layout); the segments' first points are its index buffer.
RTCGeometry Scene::newCurves(const ShapeDescription& s) {
    curveGeometry_.push_back({&s.curves, makeCurveSegments(s.curves)});
    const CurveGeometry& g = curveGeometry_.back();
    curveOfShape_[&s] = &g;
    RTCGeometry geometry = rtcNewGeometry(device_, curveType(s.curves));
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, s.curves.points.data(), 0,
                               sizeof(CurvePoint), s.curves.points.size());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, g.segments.firstPoint.data(), 0,
                               sizeof(uint32_t), g.segments.firstPoint.size());
    rtcSetGeometryUserData(geometry, const_cast<CurveGeometry*>(&g));
    rtcSetGeometryIntersectFilterFunction(geometry, curveFilter);
    rtcSetGeometryOccludedFilterFunction(geometry, curveFilter);
    return geometry;
}

// The hit point on the tube (or ribbon), the normal (the tube's, or the ribbon's, which
// faces the ray), and the texture coordinates: u along the strand, v across its width as
// the ray saw it, 0 to 1 along cross(facing, tangent). The hair material reads its offset
// h = 2 v - 1 from v (pbrt-v4's curves do the same).
void Scene::fillCurveHit(const Ray& ray, SurfaceHit& hit) const {
    const CurveGeometry& g = *curveOfSlot_[hit.shape];
    const float u = hit.barycentric.x;
    const CurveSample c = evaluateCurve(g.curves->basis, &g.curves->points[g.segments.firstPoint[hit.primitive]], u);
    const Vec3 d = normalize(ray.d);
    hit.p = ray.o + ray.d * hit.t;
    const float tangentLength = length(c.dpdu);
    const Vec3 tangent = tangentLength > 0 ? c.dpdu / tangentLength : Frame::fromNormal(d).s;
    Vec3 facing = -d - tangent * dot(-d, tangent);
    const float facingLength = length(facing);
    facing = facingLength > 1e-6f ? facing / facingLength : Frame::fromNormal(tangent).s;
    const Vec3 offset = hit.p - c.center;
    const float h = c.radius > 0 ? std::clamp(dot(offset, cross(facing, tangent)) / c.radius, -1.0f, 1.0f) : 0.0f;
    Vec3 n = facing;
    if (g.curves->profile == CurveProfile::Round) {
        const Vec3 radial = offset - tangent * dot(offset, tangent);
        const float radialLength = length(radial);
        if (radialLength > 1e-3f * c.radius) n = radial / radialLength;
    }
    hit.ng = hit.ns = n;
    const CurveSegments::Span span = g.segments.strandU[hit.primitive];
    hit.uv = {span.start + span.extent * u, 0.5f * (h + 1.0f)};
}

SurfaceTangents Scene::curveTangents(const SurfaceHit& hit) const {
    const CurveGeometry& g = *curveOfSlot_[hit.shape];
    const CurveSample c =
        evaluateCurve(g.curves->basis, &g.curves->points[g.segments.firstPoint[hit.primitive]], hit.barycentric.x);
    const CurveSegments::Span span = g.segments.strandU[hit.primitive];
    const Vec3 dpdu = c.dpdu / span.extent;  // d/du along the whole strand
    const float len = length(dpdu);
    if (!(len > 0)) return {};
    return {dpdu, cross(hit.ns, dpdu / len) * (2.0f * c.radius)};
}

}  // namespace photon
