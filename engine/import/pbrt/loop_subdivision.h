// Loop subdivision (Loop 1987) of a triangle mesh, as pbrt-v4's "loopsubdiv" shape renders
// it: `levels` rounds of splitting every triangle in four with Loop's vertex and edge
// masks (Warren's beta for the old vertices; boundary edges and vertices by the cubic
// B-spline rule, so a boundary stays a curve of its own), then every vertex moved to its
// limit position (pbrt-v3/v4's loopGamma and boundary 1/5 weights), with the normals of the
// surface at the vertices (area-weighted face normals of the final mesh).
#pragma once
#include "description/scene_description.h"

namespace photon::pbrt {

// `control`'s positions and indices (its uvs and normals are not used); winding kept.
// toLimit false: the last round's vertices as they are (for checking the masks).
TriangleMesh loopSubdivide(const TriangleMesh& control, int levels, bool toLimit = true);

}  // namespace photon::pbrt
