#include "description/curve_set.h"

namespace photon {

size_t CurveSet::segmentsOf(CurveBasis basis, size_t n) {
    switch (basis) {
        case CurveBasis::Bezier: return n >= 4 && (n - 1) % 3 == 0 ? (n - 1) / 3 : 0;
        case CurveBasis::BSpline:
        case CurveBasis::CatmullRom: return n >= 4 ? n - 3 : 0;
        case CurveBasis::Linear: return n >= 2 ? n - 1 : 0;
    }
    return 0;
}

size_t CurveSet::segmentCount() const {
    size_t total = 0;
    for (size_t k = 0; k < strandCount(); ++k) total += segmentsOf(basis, strandSize(k));
    return total;
}

CurveSegments makeCurveSegments(const CurveSet& curves) {
    CurveSegments s;
    const size_t total = curves.segmentCount();
    s.firstPoint.reserve(total);
    s.strandU.reserve(total);
    for (size_t k = 0; k < curves.strandCount(); ++k) {
        const size_t n = CurveSet::segmentsOf(curves.basis, curves.strandSize(k));
        for (size_t j = 0; j < n; ++j) {
            s.firstPoint.push_back(uint32_t(curves.strandStarts[k] + CurveSet::segmentOffset(curves.basis, j)));
            s.strandU.push_back({float(j) / float(n), 1.0f / float(n)});
        }
    }
    return s;
}

namespace {

// Weights of the four control points at u and of their derivatives, per basis: Bernstein
// polynomials; the uniform cubic B-spline's (1/6 (1-u)^3, ...); Catmull-Rom's with tension
// 1/2 (Embree's curve bases, rtcore_geometry docs).
struct Weights {
    float w[4], d[4];
};

Weights cubicWeights(CurveBasis basis, float u) {
    const float t = 1.0f - u, u2 = u * u, u3 = u2 * u;
    switch (basis) {
        case CurveBasis::Bezier:
            return {{t * t * t, 3 * u * t * t, 3 * u2 * t, u3}, {-3 * t * t, 3 * t * t - 6 * u * t, 6 * u * t - 3 * u2, 3 * u2}};
        case CurveBasis::BSpline:
            return {{t * t * t / 6, (3 * u3 - 6 * u2 + 4) / 6, (-3 * u3 + 3 * u2 + 3 * u + 1) / 6, u3 / 6},
                    {-t * t / 2, (9 * u2 - 12 * u) / 6, (-9 * u2 + 6 * u + 3) / 6, u2 / 2}};
        case CurveBasis::CatmullRom:
            return {{0.5f * (-u3 + 2 * u2 - u), 0.5f * (3 * u3 - 5 * u2 + 2), 0.5f * (-3 * u3 + 4 * u2 + u), 0.5f * (u3 - u2)},
                    {0.5f * (-3 * u2 + 4 * u - 1), 0.5f * (9 * u2 - 10 * u), 0.5f * (-9 * u2 + 8 * u + 1), 0.5f * (3 * u2 - 2 * u)}};
        case CurveBasis::Linear: break;
    }
    return {{t, u, 0, 0}, {-1, 1, 0, 0}};
}

}  // namespace

CurveSample evaluateCurve(CurveBasis basis, const CurvePoint* points, float u) {
    const Weights k = cubicWeights(basis, u);
    const int n = CurveSet::pointsPerSegment(basis);
    CurveSample s;
    for (int i = 0; i < n; ++i) {
        s.center += points[i].p * k.w[i];
        s.dpdu += points[i].p * k.d[i];
        s.radius += points[i].radius * k.w[i];
    }
    return s;
}

}  // namespace photon
