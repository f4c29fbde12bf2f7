// An environment image over the sphere of directions, in the light's own frame, with the
// density its directions are sampled by. Each texel is a patch of constant radiance (no
// filtering, as pbrt-v4's ImageInfiniteLight looks texels up): the sampling density is
// then exactly proportional to luminance, so a map of one bright texel is sampled with no
// variance from the map, and the integral of the radiance is an exact sum.
//
// Layouts (docs/scene-format.md), with u = (column + 0.5) / width across and
// v = (row + 0.5) / height down (row 0 is the image's top):
//   LatLong: theta = pi v from +y (the top row is up, the bottom row down) and
//            phi = 2 pi u, direction (-sin theta sin phi, cos theta, sin theta cos phi):
//            u = 0 faces +z, u = 1/4 faces -x, u = 1/2 faces -z, u = 3/4 faces +x. Seen
//            from inside (a camera looking down -z, +x to its right, as photon's default
//            camera) the panorama reads left to right, not mirrored.
//   EqualArea: pbrt-v4's square (math/equal_area.h) of (u, v), its +z at the centre.
#pragma once
#include <memory>
#include <optional>
#include "math/equal_area.h"
#include "math/piecewise_constant.h"
#include "description/scene_description.h"

namespace photon {

class EnvironmentMap {
public:
    // Throws std::invalid_argument if an equal-area image is not square.
    EnvironmentMap(std::shared_ptr<const ImageTexture> image, EnvironmentLayout layout);

    // The texel the direction d (unit, light frame) falls in.
    TexelIndex texelOf(Vec3 d) const;
    Color radiance(Vec3 d) const {
        TexelIndex t = texelOf(d);
        return image_->texel(t.x, t.y);
    }
    // The solid angle texel row y covers per texel.
    float texelSolidAngle(int y) const { return texelSolidAngle_[size_t(y)]; }
    // The integral of the radiance over the sphere of directions, per channel.
    Color integral() const { return integral_; }
    // The luminance of the irradiance the map gives a surface facing its pole (+y of a
    // lat-long map, +z of an equal-area one): the sum over texels of luminance x cos x solid
    // angle at their centres, as pbrt-v4 measures an image light's "illuminance".
    float poleIrradiance() const;

    struct DirectionSample {
        Vec3 direction;  // unit, light frame
        Color radiance;
        float pdf;       // solid-angle density
    };
    // A direction with density proportional to luminance; nothing if the map is black.
    std::optional<DirectionSample> sample(Vec2 u) const;
    // The solid-angle density sample() draws d with.
    float pdf(Vec3 d) const {
        TexelIndex t = texelOf(d);
        return texelProbability(t) / texelSolidAngle(t.y);
    }

private:
    float texelProbability(TexelIndex t) const { return distribution_.cellProbability(t.x, t.y); }
    // The direction at (x, y) within texel row `row` of [0,1)^2, solid angle spread evenly.
    Vec3 directionAt(Vec2 p, int row) const;

    std::shared_ptr<const ImageTexture> image_;
    EnvironmentLayout layout_;
    int width_, height_;
    std::vector<float> texelSolidAngle_;  // by row
    std::vector<float> cosThetaEdge_;     // LatLong: cos theta at the top of each row, and the bottom
    PiecewiseConstant2D distribution_;    // luminance x solid angle, by texel
    Color integral_{0.0f};
};

// The factor on an image's texels: `scale`, times illuminance / poleIrradiance when an
// illuminance is asked for (1 if the map gives none there).
float environmentScale(const LightDescription::EnvironmentImage& e, const EnvironmentMap& map);

}  // namespace photon
