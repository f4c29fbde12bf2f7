// Sampling the directions a triangle subtends, uniformly in solid angle (Arvo 1995,
// "Stratified Sampling of Spherical Triangles"; the formulation of pbrt-v4, sec. 6.5.4).
// Light samples drawn so carry no 1 / d^2 and no cosine at the light, the factors that make
// sampling a large nearby area light by area noisy.
#pragma once
#include <optional>
#include <photon/vec.h>

namespace photon {

// Below this solid angle (steradians) the spherical formulas lose their digits in float;
// callers sample by area instead (pbrt-v4's MinSphericalSampleArea).
inline constexpr float kMinSphericalTriangleSolidAngle = 3e-4f;

// The solid angle the triangle (v0, v1, v2) subtends from p (Van Oosterom & Strackee 1983),
// in steradians; 0 if p lies in its plane.
float sphericalTriangleSolidAngle(Vec3 p, Vec3 v0, Vec3 v1, Vec3 v2);

// A unit direction from p toward the triangle, uniform over the solid angle it subtends
// (density 1 / sphericalTriangleSolidAngle), from two uniform numbers; none if the
// triangle is degenerate as seen from p.
std::optional<Vec3> sampleSphericalTriangle(Vec3 p, Vec3 v0, Vec3 v1, Vec3 v2, Vec2 u);

// The inverse: the two numbers from which sampleSphericalTriangle draws the direction w (a
// unit vector from p inside the triangle); none if the triangle is degenerate. The corners
// of [0,1]^2 go to v1 ((0,0) and (1,0)), v0 (0,1) and v2 (1,1).
std::optional<Vec2> invertSphericalTriangleSample(Vec3 p, Vec3 v0, Vec3 v1, Vec3 v2, Vec3 w);

}  // namespace photon
