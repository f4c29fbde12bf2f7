// Light samples on the triangles of a mesh light that follow what each part of them brings
// to the receiver. What of each triangle lies above the receiver's plane (clipped_triangle.h)
// is cut into triangles, its pieces, and each piece is sampled in one of two ways:
//
// - Close by (the receiver within four times the piece's radius of its centre), by solid
//   angle warped by the receiver's cosine: the two numbers are drawn from a bilinear density
//   whose corners hold the receiver's cosine toward the piece's corners (bilinear_density.h),
//   then mapped to a direction uniform in the piece's solid angle (spherical_triangle.h).
//   That is pbrt-v4's light sample on a triangle seen from a point with a normal
//   (Triangle::Sample; Hart et al. 2020): uniform solid angle takes away the 1 / d^2 and the
//   light's cosine, whose peak under a light no fit of its corners follows, and what is
//   left, the receiver's cosine, is smooth across the light and runs to 0 at the horizon,
//   where a light beside a surface stands. A corner counts at least 0.01 (pbrt-v4's floor).
// - Farther away (or where the piece subtends too little for the spherical formulas in
//   float), by area with a density linear in the barycentric coordinates, through the
//   piece's corners' geometric term cos_receiver cos_light / d^2: a vertex picked in
//   proportion to its term, then a point with density proportional to its weight on that
//   vertex (Beta(2, 2) in it, uniform along the rest). Seen from afar the term is nearly
//   linear over the piece, and this costs no trigonometry but one asin and one sin; the
//   spherical formulas in double made a path on the Cornell box 1.6 times as slow.
//
// A piece is picked in proportion to its estimated share: its solid angle times its corners'
// mean cosine, or its area times their mean term (the same integral, by either measure).
// Either way the density of a direction is the piece's fitted value there over the sum of
// the shares: by solid angle for the first, by area for the second.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include "math/bilinear_density.h"
#include "math/clipped_triangle.h"
#include "math/sampling.h"
#include "math/spherical_triangle.h"

namespace photon {

class WarpedLightPieces {
public:
    static constexpr int kMaxPieces = 8;  // two for each of four triangles
    // Closer than this many times a piece's radius to its centre, it is sampled by solid angle.
    static constexpr float kNear = 4;

    // p, n: the receiver; `cosine`: whether it weighs light by its cosine to n (a surface)
    // or not (a point in a medium, for which n only splits the sphere in two).
    // `fitted` false: pieces are sampled by solid angle only within one radius of their
    // centre, and uniformly by area elsewhere (ReceiverSide::fitted).
    WarpedLightPieces(Vec3 p, Vec3 n, bool cosine, bool fitted = true)
        : p_(p), n_(n), cosine_(cosine), near_(fitted ? kNear : 1.0f), fitted_(fitted) {}

    // Adds the part of the mesh's triangle `index` (corners v0, v1, v2, area `wholeArea`,
    // emitting side's normal `face`) above the receiver's plane.
    void add(uint32_t index, const ClippedTriangle& part, Vec3 v0, Vec3 v1, Vec3 v2, float wholeArea, Vec3 face) {
        if (!(part.area > 0)) return;
        if (part.whole) {
            push(index, v0, v1, v2, wholeArea, face);
            return;
        }
        push(index, part.corner[0], part.corner[1], part.corner[2], part.fanArea0, face);
        if (part.corners == 4) push(index, part.corner[0], part.corner[2], part.corner[3], part.area - part.fanArea0, face);
    }

    // Fills the pieces' fits and shares; call once, after every add().
    void weigh() {
        total_ = 0;
        for (int k = 0; k < count_; ++k) {
            Piece& piece = pieces_[k];
            const Vec3 centre = (piece.v[0] + piece.v[1] + piece.v[2]) * (1.0f / 3.0f);
            float radius2 = 0;
            for (const Vec3& v : piece.v) radius2 = std::max(radius2, lengthSquared(v - centre));
            piece.spherical = lengthSquared(p_ - centre) < near_ * near_ * radius2;
            if (piece.spherical) {
                piece.solidAngle = sphericalTriangleSolidAngle(p_, piece.v[0], piece.v[1], piece.v[2]);
                piece.spherical = piece.solidAngle >= kMinSphericalTriangleSolidAngle;
            }
            float share;
            if (piece.spherical) {
                // sampleSphericalTriangle's corners: (0,0) and (1,0) go to v[1], (0,1) to v[0], (1,1) to v[2].
                const float c0 = cosineToward(piece.v[0]), c1 = cosineToward(piece.v[1]), c2 = cosineToward(piece.v[2]);
                piece.corners = BilinearCorners{{c1, c1, c0, c2}};
                share = piece.solidAngle * piece.corners.mean();
            } else {
                float largest = 0;
                for (int c = 0; c < 3; ++c)
                    largest = std::max(largest, piece.term[c] = fitted_ ? geometry(piece.v[c], piece.face) : 0.0f);
                // Every corner 0 (a sliver on the horizon), or not fitted: uniform.
                for (float& t : piece.term) t = largest > 0 ? std::max(t, 0.01f * largest) : 1.0f;
                piece.termSum = piece.term[0] + piece.term[1] + piece.term[2];
                share = piece.area * piece.termSum / 3;
            }
            total_ += share;
            cumulative_[k] = total_;
        }
    }

    struct Sample {
        Vec3 wi;
        uint32_t triangle;
        float pdf;  // in solid angle
    };
    std::optional<Sample> sample(Vec2 u) const {
        if (!(total_ > 0)) return std::nullopt;
        const float x = u.x * total_;
        int k = 0;
        while (k + 1 < count_ && x >= cumulative_[k]) ++k;
        const Piece& piece = pieces_[k];
        const float below = k > 0 ? cumulative_[k - 1] : 0.0f;
        const float share = cumulative_[k] - below;
        if (!(share > 0)) return std::nullopt;
        const Vec2 uWithin{std::clamp((x - below) / share, 0.0f, 0.99999994f), u.y};
        if (piece.spherical) {
            const Vec2 w = sampleBilinear(uWithin, piece.corners);
            const std::optional<Vec3> wi = sampleSphericalTriangle(p_, piece.v[0], piece.v[1], piece.v[2], w);
            if (!wi) return std::nullopt;
            return Sample{*wi, piece.triangle, piece.corners.at(w) / total_};
        }
        const Vec3 y = pointByTerms(piece, uWithin);
        const Vec3 d = y - p_;
        const float d2 = lengthSquared(d);
        if (!(d2 > 0)) return std::nullopt;
        const Vec3 wi = d / std::sqrt(d2);
        const float pdf = planarDensity(piece, y, wi, d2);
        if (!(pdf > 0)) return std::nullopt;
        return Sample{wi, piece.triangle, pdf};
    }

    // The density in solid angle with which sample() draws the direction from the receiver
    // to the point y of the mesh's triangle `index`.
    float density(uint32_t index, Vec3 y) const {
        if (!(total_ > 0)) return 0.0f;
        // The triangle's piece that y lies deepest in: pieces sharing an edge give its points
        // different densities, so one just across it must not be taken for the other's.
        int best = -1;
        float deepest = -1e-4f;
        for (int k = 0; k < count_; ++k)
            if (pieces_[k].triangle == index) {
                const float depth = depthIn(pieces_[k], y);
                if (depth > deepest) best = k, deepest = depth;
            }
        if (best < 0) return 0.0f;
        const Piece& piece = pieces_[best];
        const Vec3 d = y - p_;
        const float d2 = lengthSquared(d);
        if (!(d2 > 0)) return 0.0f;
        const Vec3 wi = d / std::sqrt(d2);
        if (!piece.spherical) return planarDensity(piece, y, wi, d2);
        const std::optional<Vec2> w = invertSphericalTriangleSample(p_, piece.v[0], piece.v[1], piece.v[2], wi);
        return w ? piece.corners.at(*w) / total_ : 0.0f;
    }

private:
    // Filled by push() and weigh(); left uninitialised before, since a light sample builds
    // eight of them and uses two.
    struct Piece {
        Vec3 v[3];
        Vec3 face;
        uint32_t triangle;
        float area, solidAngle;
        bool spherical;
        BilinearCorners corners;  // spherical: the receiver's cosines
        float term[3], termSum;   // planar: the geometric term at each corner
    };

    void push(uint32_t index, Vec3 v0, Vec3 v1, Vec3 v2, float area, Vec3 face) {
        if (!(area > 0) || count_ == kMaxPieces) return;
        Piece& piece = pieces_[count_++];
        piece.v[0] = v0, piece.v[1] = v1, piece.v[2] = v2;
        piece.face = face, piece.triangle = index, piece.area = area, piece.solidAngle = 0;
    }
    float cosineToward(Vec3 v) const {
        if (!cosine_) return 1.0f;
        const Vec3 d = v - p_;
        const float l2 = lengthSquared(d);
        return l2 > 0 ? std::max(0.01f, dot(n_, d) / std::sqrt(l2)) : 1.0f;
    }
    // cos_receiver cos_light / d^2 from the corner v of a face of normal `face`.
    float geometry(Vec3 v, Vec3 face) const {
        const Vec3 d = v - p_;
        const float d2 = lengthSquared(d);
        if (!(d2 > 0)) return 0.0f;
        const float inv = 1.0f / std::sqrt(d2);
        const float cosLight = std::abs(dot(face, d)) * inv;
        const float cosReceiver = cosine_ ? std::max(0.0f, dot(n_, d) * inv) : 1.0f;
        return cosLight * cosReceiver / d2;
    }
    // A point of the piece with density by area proportional to the terms' linear blend.
    static Vec3 pointByTerms(const Piece& piece, Vec2 u) {
        const float x = u.x * piece.termSum;
        const int i = x < piece.term[0] ? 0 : x < piece.term[0] + piece.term[1] ? 1 : 2;
        const float below = i == 0 ? 0.0f : i == 1 ? piece.term[0] : piece.term[0] + piece.term[1];
        const float v = std::clamp((x - below) / piece.term[i], 0.0f, 1.0f);
        // Beta(2, 2), the density of vertex i's weight under a density proportional to it:
        // its CDF 3b^2 - 2b^3 inverted.
        const float b = 0.5f - std::sin(std::asin(1.0f - 2.0f * v) / 3.0f);
        const Vec3& own = piece.v[i];
        const Vec3& next = piece.v[(i + 1) % 3];
        const Vec3& last = piece.v[(i + 2) % 3];
        return own * b + (next * u.y + last * (1.0f - u.y)) * (1.0f - b);
    }
    // The piece's density by area at y, term-weighted, in solid angle.
    float planarDensity(const Piece& piece, Vec3 y, Vec3 wi, float d2) const {
        const float cosLight = std::abs(dot(piece.face, wi));
        if (!(cosLight > 0)) return 0.0f;
        const Vec3 b = barycentrics(piece, y);
        const float fitted = std::max(0.0f, b.x * piece.term[0] + b.y * piece.term[1] + b.z * piece.term[2]);
        return fitted / total_ * d2 / cosLight;
    }
    // y's barycentric coordinates in the piece (y on the triangle's plane).
    static Vec3 barycentrics(const Piece& piece, Vec3 y) {
        const std::optional<Vec2> b = planeCoordinates(y, piece.v[0], piece.v[1] - piece.v[0], piece.v[2] - piece.v[0]);
        if (!b) return Vec3(-1.0f);
        return {1 - b->x - b->y, b->x, b->y};
    }
    static float depthIn(const Piece& piece, Vec3 y) {
        const Vec3 b = barycentrics(piece, y);
        return std::min({b.x, b.y, b.z});
    }

    Vec3 p_, n_;
    bool cosine_;
    float near_;
    bool fitted_;
    Piece pieces_[kMaxPieces];
    float cumulative_[kMaxPieces];
    int count_ = 0;
    float total_ = 0;
};

}  // namespace photon
