// Placing a shape description in another frame: what a shape's own "transform" does, and
// what an instanced object's emitters need to become world-space lights.
#pragma once
#include <optional>
#include "description/scene_description.h"

namespace photon {

// The factor s if `t` is a rotation (possibly with reflection) times a uniform scale s.
std::optional<float> uniformScale(const Transform& t);
// Transforms positions and normals; swaps the winding if `t` mirrors, so the geometric
// normal keeps agreeing with the shading normals (and with the side a quad emits to).
void applyTransform(const Transform& t, TriangleMesh& mesh);
// Moves the control points; radii scale by the cube root of |det t|.
void applyTransform(const Transform& t, CurveSet& curves);
// The shape moved by `t`. False, and the shape unchanged, for a sphere that `t` does not
// keep a sphere (any scale that is not uniform).
bool transformShape(const Transform& t, ShapeDescription& shape);

}  // namespace photon
