// Perspective camera with an optional thin lens.
#pragma once
#include "math/frame.h"
#include "math/sampling.h"
#include "math/ray.h"

namespace photon {

struct CameraDescription;

class Camera {
public:
    Camera() = default;
    explicit Camera(const CameraDescription& d);

    // A ray through film position (x, y) in pixels (y down), with lens sample uLens.
    Ray generateRay(float x, float y, Vec2 uLens) const;
    int width() const { return width_; }
    int height() const { return height_; }
    // Side of one pixel at unit distance along the view axis.
    float pixelAngle() const { return pixelAngle_; }

private:
    Vec3 position_, right_, up_, forward_;
    float tanHalfFov_ = 1, aspect_ = 1, pixelAngle_ = 0, apertureRadius_ = 0, focusDistance_ = 1;
    int width_ = 1, height_ = 1;
};

}  // namespace photon
