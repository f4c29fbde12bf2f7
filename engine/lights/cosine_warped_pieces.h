// Light samples on a mesh light of a few triangles (a quad's two) by the solid angle its
// parts subtend, warped by the receiver's cosine. What of each triangle lies above the
// receiver's plane (clipped_triangle.h) is cut into triangles, its pieces. Within a piece
// the direction is uniform in solid angle (spherical_triangle.h) after the two numbers are
// drawn from a bilinear density whose corners hold the receiver's cosine toward the piece's
// corners there (bilinear_density.h); a piece is picked in proportion to its solid angle
// times the mean of its corners. That is pbrt-v4's light sample on a triangle seen from a
// point with a normal (Triangle::Sample; Hart et al. 2020): uniform solid angle takes away
// the 1 / d^2 and the light's cosine, whose peak under a light no fit of its corners
// follows, and what is left of the irradiance integral, the receiver's cosine, is smooth
// across the light and runs to 0 at the horizon, where a light beside a surface stands.
// A corner's cosine counts at least 0.01 (pbrt-v4's floor), so no part goes unsampled.
//
// A piece too small for the spherical formulas in float (kMinSphericalTriangleSolidAngle)
// is sampled uniformly by area instead, still picked by its solid angle.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include "math/bilinear_density.h"
#include "math/clipped_triangle.h"
#include "math/spherical_triangle.h"

namespace photon {

class CosineWarpedPieces {
public:
    static constexpr int kMaxPieces = 8;  // two for each of four triangles

    // p, n: the receiver; `cosine`: whether it weighs light by its cosine to n (a surface)
    // or not (a point in a medium, for which n only splits the sphere in two).
    CosineWarpedPieces(Vec3 p, Vec3 n, bool cosine) : p_(p), n_(n), cosine_(cosine) {}

    // Adds the part of the mesh's triangle `index` (corners v0, v1, v2 and area `wholeArea`)
    // above the receiver's plane.
    void add(uint32_t index, const ClippedTriangle& part, Vec3 v0, Vec3 v1, Vec3 v2, float wholeArea) {
        if (!(part.area > 0)) return;
        if (part.whole) {
            push(index, v0, v1, v2, wholeArea);
            return;
        }
        push(index, part.corner[0], part.corner[1], part.corner[2], part.fanArea0);
        if (part.corners == 4) push(index, part.corner[0], part.corner[2], part.corner[3], part.area - part.fanArea0);
    }

    struct Sample {
        Vec3 wi;
        uint32_t triangle;
        float pdf;  // in solid angle
    };
    // A direction toward the light; `face` gives the normal of the mesh's triangle.
    template <class FaceOf>
    std::optional<Sample> sample(Vec2 u, FaceOf face) const {
        if (!(total_ > 0)) return std::nullopt;
        const float x = u.x * total_;
        int k = 0;
        while (k + 1 < count_ && x >= cumulative_[k]) ++k;
        const Piece& piece = pieces_[k];
        const float below = k > 0 ? cumulative_[k - 1] : 0.0f;
        const float share = cumulative_[k] - below;
        if (!(share > 0)) return std::nullopt;
        const Vec2 uWithin{std::clamp((x - below) / share, 0.0f, 0.99999994f), u.y};
        if (piece.byArea) {
            const Vec2 b = sampleUniformTriangle(uWithin);
            const Vec3 y = piece.v[0] * (1 - b.x - b.y) + piece.v[1] * b.x + piece.v[2] * b.y;
            const Vec3 d = y - p_;
            const float d2 = lengthSquared(d);
            if (!(d2 > 0)) return std::nullopt;
            const Vec3 wi = d / std::sqrt(d2);
            const float pdf = areaPieceDensity(piece, wi, d2, face(piece.triangle));
            if (!(pdf > 0)) return std::nullopt;
            return Sample{wi, piece.triangle, pdf};
        }
        const Vec2 w = sampleBilinear(uWithin, piece.corners);
        const std::optional<Vec3> wi = sampleSphericalTriangle(p_, piece.v[0], piece.v[1], piece.v[2], w);
        if (!wi) return std::nullopt;
        return Sample{*wi, piece.triangle, piece.corners.at(w) / total_};
    }

    // The density in solid angle with which sample() draws the direction from the receiver
    // to the point y of the mesh's triangle `index` (of normal `face`).
    float density(uint32_t index, Vec3 y, Vec3 face) const {
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
        if (piece.byArea) return areaPieceDensity(piece, wi, d2, face);
        const std::optional<Vec2> w = invertSphericalTriangleSample(p_, piece.v[0], piece.v[1], piece.v[2], wi);
        return w ? piece.corners.at(*w) / total_ : 0.0f;
    }

    // Fills the pieces' corners and picking weights; call once, after every add().
    void weigh() {
        total_ = 0;
        for (int k = 0; k < count_; ++k) {
            Piece& piece = pieces_[k];
            piece.solidAngle = sphericalTriangleSolidAngle(p_, piece.v[0], piece.v[1], piece.v[2]);
            piece.byArea = piece.solidAngle < kMinSphericalTriangleSolidAngle;
            // sampleSphericalTriangle's corners: (0,0) and (1,0) go to v[1], (0,1) to v[0], (1,1) to v[2].
            const float c0 = cosineToward(piece.v[0]), c1 = cosineToward(piece.v[1]), c2 = cosineToward(piece.v[2]);
            piece.corners = BilinearCorners{{c1, c1, c0, c2}};
            total_ += piece.solidAngle * piece.corners.mean();
            cumulative_[k] = total_;
        }
    }

    int count() const { return count_; }

private:
    struct Piece {
        Vec3 v[3];
        uint32_t triangle = 0;
        float area = 0, solidAngle = 0;
        bool byArea = false;
        BilinearCorners corners{};
    };

    void push(uint32_t index, Vec3 v0, Vec3 v1, Vec3 v2, float area) {
        if (!(area > 0) || count_ == kMaxPieces) return;
        pieces_[count_++] = Piece{{v0, v1, v2}, index, area, 0.0f, false, {}};
    }
    float cosineToward(Vec3 v) const {
        if (!cosine_) return 1.0f;
        const Vec3 d = v - p_;
        const float l2 = lengthSquared(d);
        return l2 > 0 ? std::max(0.01f, dot(n_, d) / std::sqrt(l2)) : 1.0f;
    }
    // A piece sampled by area: its pick times d^2 / (cos_light area).
    float areaPieceDensity(const Piece& piece, Vec3 wi, float d2, Vec3 face) const {
        const float cosLight = std::abs(dot(face, wi));
        if (!(cosLight > 0)) return 0.0f;
        return piece.solidAngle * piece.corners.mean() / total_ * d2 / (cosLight * piece.area);
    }
    // The smallest of y's barycentric coordinates in the piece (y on the triangle's plane):
    // negative outside it.
    static float depthIn(const Piece& piece, Vec3 y) {
        const Vec3 e0 = piece.v[1] - piece.v[0], e1 = piece.v[2] - piece.v[0], d = y - piece.v[0];
        const float d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d0 = dot(d, e0), d1 = dot(d, e1);
        const float det = d00 * d11 - d01 * d01;
        if (!(det > 0)) return -1.0f;
        const float b1 = (d11 * d0 - d01 * d1) / det, b2 = (d00 * d1 - d01 * d0) / det;
        return std::min({b1, b2, 1 - b1 - b2});
    }

    Vec3 p_, n_;
    bool cosine_;
    Piece pieces_[kMaxPieces];
    float cumulative_[kMaxPieces] = {};
    int count_ = 0;
    float total_ = 0;
};

}  // namespace photon
