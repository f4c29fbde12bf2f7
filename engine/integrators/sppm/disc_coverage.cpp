#include "integrators/sppm/disc_coverage.h"
#include <algorithm>
#include <cmath>
#include "integrators/common/shading.h"
#include "math/frame.h"
#include "math/ray.h"
#include "scene/scene.h"

namespace photon {

namespace {
// Surfaces a ray may pass on its way: glass, smooth or rough, and mirrors receive no photons
// and let them through (or around) to what lies behind, and a sheet that transmits (diffuse
// transmission) lights what is behind it. A few, so that a stack of them cannot cost much.
constexpr int kPassable = 3;
// Near the rim a column's half height, sqrt(1 - s) r, goes to 0; it keeps at least this
// share of r, so that its ray starts clear of the surface it is to find.
constexpr float kLeastHalfHeight = 0.25f;
// The height over the surface, in r, at which a column's foot is looked for from the centre.
constexpr float kLookHeight = 0.05f;
// Surfaces facing elsewhere the way to a column's foot is followed through (two posts'
// sides each); a way that crosses more counts as ending inside.
constexpr int kMostCrossings = 4;
constexpr float kGoldenFraction = 0.61803398875f;
constexpr float kLargestRadiusSquared = 1e30f;  // r up to 1e15

enum class Found { Nothing, Facing, FacingElsewhere };

// The next surface along `ray` that photons land on and that does not let them through,
// seen from the ray's origin: one facing as the disc's normal n does (the gather's own test,
// sppm_gather.cpp), or one that does not. A sheet that transmits counts where it faces as
// the disc does (photons land on it) and is passed where it does not. Nothing once no
// surface is left or `hitsLeft` surfaces were met (glass and mirrors passed among them);
// `ray` goes on from just past the surface found, with what is left of its length.
Found nextPhotonSurface(const Scene& scene, Ray& ray, Vec3 n, bool transmits, int& hitsLeft) {
    while (hitsLeft-- > 0) {
        SurfaceHit hit;
        if (!scene.intersect(ray, hit)) return Found::Nothing;
        const Material& m = scene.material(hit);
        Found found = Found::Nothing;
        if (!(m.isDeltaOnly() || m.refractiveIndex().has_value())) {
            turnTowardViewer(m, hit, -ray.d);
            const float facing = dot(n, hit.ns);
            if ((transmits ? std::abs(facing) : facing) >= 0.5f) found = Found::Facing;
            else if (!m.transmits()) found = Found::FacingElsewhere;
        }
        const float left = ray.tMax - hit.t;
        ray = spawnRay(hit.p, hit.ng, ray.d);
        ray.tMax = left;
        if (found != Found::Nothing) return found;
    }
    return Found::Nothing;
}

// Whether the way from the centre to a column's foot, `ray` (just over the surface, as long
// as the way), ends inside something standing on the disc: it crosses surfaces facing
// elsewhere an odd number of times before its end, or more often than is worth following.
// One crossing is a box's side, the foot under the box, where no photon comes; two are a
// post or a table's leg passed through, the foot on the floor behind it, where photons come
// from above and the gather counts them as it counts any in its sphere. A surface facing
// as the disc does on the way is the disc's own rising (a bowl's inside), not a wall: the
// way ends there, on the surface.
bool wayEndsInside(const Scene& scene, Ray ray, Vec3 n, bool transmits) {
    int crossed = 0, hitsLeft = kPassable + kMostCrossings + 1;
    for (;;) {
        const Found found = nextPhotonSurface(scene, ray, n, transmits, hitsLeft);
        if (found != Found::FacingElsewhere) return crossed % 2 == 1;
        if (++crossed > kMostCrossings) return true;
    }
}

// Whether photons land under the disc at `offset` (in its plane) from its centre p: the
// column there, from the sphere's top down through it, first meets a surface facing as the
// disc does, and the way to it from the centre does not end inside something standing on
// the disc (a column inside a box on the floor would find the floor under it, or the box's
// bottom face, which a two-sided material turns up).
bool photonsLandAt(const Scene& scene, Vec3 p, Vec3 n, Vec3 offset, float r, float half, bool transmits) {
    // The column first: where it finds nothing (past a wall, over a cliff) the way is not cast.
    Ray column{p + offset + n * half, -n, 2.0f * half};
    int hitsLeft = kPassable + 1;
    if (nextPhotonSurface(scene, column, n, transmits, hitsLeft) != Found::Facing) return false;
    const float d = length(offset);
    return !(d > 0) || !wayEndsInside(scene, Ray{p + n * (kLookHeight * r), offset / d, d}, n, transmits);
}

// The k-th of the spiral's columns: its offset from the centre in the disc's plane, its
// s = d^2 / r^2 = (k + 1/2) / K (equal areas), and its half height.
struct Column {
    Vec3 offset;
    float s, half;
};
Column columnOf(int k, const Frame& frame, float r, float turn) {
    const float s = (static_cast<float>(k) + 0.5f) / kDiscCoverageColumns;
    const float turns = static_cast<float>(k) * kGoldenFraction + turn;
    const float phi = 2.0f * kPi * (turns - std::floor(turns));
    const float d = r * std::sqrt(s);
    return {frame.s * (d * std::cos(phi)) + frame.t * (d * std::sin(phi)), s,
            r * std::max(std::sqrt(1.0f - s), kLeastHalfHeight)};
}
}  // namespace

DiscCoverage measureDiscCoverage(const Scene& scene, Vec3 p, Vec3 n, float r2, bool transmits, KernelKind kernel,
                                 float turn) {
    // A radius no ray can be cast with (a damaged checkpoint's) leaves the disc whole: Embree
    // takes no ray whose origin or direction has a coordinate beyond 1.8e18.
    if (!(r2 > 0) || !(r2 < kLargestRadiusSquared)) return {};
    const Frame frame = Frame::fromNormal(n);
    const float r = std::sqrt(r2);
    float all = 0, covered = 0, spread = 0;
    int columns = 0;
    for (int k = 0; k < kDiscCoverageColumns; ++k) {
        const Column c = columnOf(k, frame, r, turn);
        const float w = kernelWeight(kernel, c.s);
        all += w;
        if (!photonsLandAt(scene, p, n, c.offset, r, c.half, transmits)) continue;
        covered += w;
        spread += c.s;  // unweighted, as the photons' spread is summed
        ++columns;
    }
    // The column nearest the centre stands on the point itself; should every one miss (a
    // sliver of a surface), the disc is taken whole rather than divided by nothing.
    if (!(covered > 0)) return {};
    return {covered / all, spread / static_cast<float>(columns)};
}

}  // namespace photon
