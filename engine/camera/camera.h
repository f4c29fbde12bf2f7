// Perspective camera with an optional thin lens, an orthographic one, or a spherical one
// that sees every direction (an equal-area square or an equirectangular panorama).
#pragma once
#include "math/frame.h"
#include "math/sampling.h"
#include "math/ray.h"
#include <memory>
#include "camera/lens_system.h"
#include "camera/pixel_filter.h"
#include "description/camera_projection.h"

namespace photon {

struct CameraDescription;

class Camera {
public:
    Camera() = default;
    explicit Camera(const CameraDescription& d);

    // A ray through film position (x, y) in pixels (y down), with lens sample uLens.
    Ray generateRay(float x, float y, Vec2 uLens) const;

    // A film position for pixel (x, y) drawn from the pixel filter with u, and the weight
    // the sample's radiance takes in the pixel's mean (pixel_filter.h): with the default
    // box, (x, y) + u and weight 1.
    struct FilmSample {
        float x, y, weight;
    };
    FilmSample sampleFilm(int x, int y, Vec2 u) const {
        if (filter_.unitBox()) return {static_cast<float>(x) + u.x, static_cast<float>(y) + u.y, 1.0f};
        const PixelFilter::Sample s = filter_.sample(u);
        return {static_cast<float>(x) + 0.5f + s.offset.x, static_cast<float>(y) + 0.5f + s.offset.y, s.weight};
    }
    // The ray and the weight of a sample of pixel (x, y): u for the film, uLens for the lens.
    struct PixelSample {
        Ray ray;
        float weight;
    };
    PixelSample samplePixel(int x, int y, Vec2 u, Vec2 uLens) const {
        const FilmSample f = sampleFilm(x, y, u);
        if (lens_) [[unlikely]] return throughLens(f, uLens);
        return {generateRay(f.x, f.y, uLens), f.weight};
    }
    // Whether rays start across a lens (the uLens of samplePixel matters) or at a pinhole.
    bool hasLens() const { return apertureRadius_ > 0 || lens_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // Side of one pixel where a camera ray has travelled `distance` (along the view axis, and
    // past mirrors): grows with it through a perspective or spherical camera, not through an
    // orthographic one.
    float pixelFootprint(float distance) const {
        return projection_ == Projection::Orthographic ? pixelSize_ : distance * pixelAngle_;
    }

private:
    using Projection = CameraProjection;
    using SphericalMapping = CameraSphericalMapping;
    Vec3 sphericalDirection(float x, float y) const;
    // A lens system's sample, in the world: weight 0 (and a ray along the view) where the
    // system stops it, else the filter's weight times the lens's (LensSystem::sample).
    PixelSample throughLens(const FilmSample& f, Vec2 uLens) const;

    Vec3 position_, right_, up_, forward_;
    float tanHalfFov_ = 1, aspect_ = 1, pixelAngle_ = 0, apertureRadius_ = 0, focusDistance_ = 1;
    Projection projection_ = Projection::Perspective;
    SphericalMapping mapping_ = SphericalMapping::EqualArea;
    float halfHeight_ = 1, pixelSize_ = 0;  // orthographic: half the view's height, one pixel's side
    int width_ = 1, height_ = 1;
    PixelFilter filter_;
    std::shared_ptr<const LensSystem> lens_;  // CameraProjection::LensSystem
};

}  // namespace photon
