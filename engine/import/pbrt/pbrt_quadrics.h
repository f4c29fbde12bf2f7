// pbrt-v4's quadrics that photon renders as triangle meshes: partial spheres, cylinders and
// disks, with pbrt's (u, v) and the surfaces' exact normals at the vertices (so shading is
// smooth), facing out of the sphere or cylinder and +z for the disk (pbrt-v4's shapes.h).
#pragma once
#include "description/scene_description.h"

namespace photon::pbrt {

// Angles in degrees as pbrt's "phimax"; z and radii in the shape's own units.
TriangleMesh partialSphereMesh(double radius, double zMin, double zMax, double phiMaxDegrees);
TriangleMesh cylinderMesh(double radius, double zMin, double zMax, double phiMaxDegrees);
TriangleMesh diskMesh(double height, double radius, double innerRadius, double phiMaxDegrees);

}  // namespace photon::pbrt
