// Curves: strands of control points with a radius each (hair, fur, grass), swept into thin
// tubes or camera-facing ribbons by Embree's curve primitives. docs/scene-format.md#curves.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>
#include <photon/vec.h>

namespace photon {

// How a strand's control points make a curve, one cubic segment (two points for linear)
// at a time: Bezier segments share their end points (3k + 1 points for k segments); the
// uniform cubic B-spline and Catmull-Rom make a segment of every four consecutive points
// (n - 3 segments; neither reaches its first and last point); linear joins the points.
enum class CurveBasis { Bezier, BSpline, CatmullRom, Linear };
// The surface swept along the curve: a round tube, or a flat ribbon that turns to face each
// ray (cheaper; pbrt-v4's "flat" curves).
enum class CurveProfile { Round, Flat };

// A control point and the curve's radius there: Embree's vertex layout (RTC_FORMAT_FLOAT4).
struct CurvePoint {
    Vec3 p;
    float radius = 0;
};

// A point on a curve: the centre line's position, its derivative d/du along the segment
// and the radius.
struct CurveSample {
    Vec3 center, dpdu;
    float radius = 0;
};

struct CurveSet {
    CurveBasis basis = CurveBasis::Bezier;
    CurveProfile profile = CurveProfile::Round;
    std::vector<CurvePoint> points;
    // Strand k is points [strandStarts[k], strandStarts[k + 1]) (the last runs to the end).
    std::vector<uint32_t> strandStarts;

    size_t strandCount() const { return strandStarts.size(); }
    size_t strandSize(size_t k) const {
        return (k + 1 < strandStarts.size() ? strandStarts[k + 1] : points.size()) - strandStarts[k];
    }
    // How many segments a strand of n points has under the basis (0 if too short, or for
    // Bezier if n is not 3k + 1).
    static size_t segmentsOf(CurveBasis basis, size_t n);
    // Points each segment reads: 4, or 2 for linear.
    static int pointsPerSegment(CurveBasis basis) { return basis == CurveBasis::Linear ? 2 : 4; }
    // Index of the j-th segment's first point within its strand.
    static size_t segmentOffset(CurveBasis basis, size_t j) { return basis == CurveBasis::Bezier ? 3 * j : j; }
    size_t segmentCount() const;
};

// The segments Embree intersects: each one's first point (its index buffer) and where it
// lies along its strand, for the texture coordinate u that runs 0 to 1 along the strand.
struct CurveSegments {
    std::vector<uint32_t> firstPoint;
    struct Span {
        float start, extent;
    };
    std::vector<Span> strandU;
};
CurveSegments makeCurveSegments(const CurveSet& curves);

// The curve of one segment at u in [0, 1], from its first control point (4 read, 2 for
// linear).
CurveSample evaluateCurve(CurveBasis basis, const CurvePoint* points, float u);

}  // namespace photon
