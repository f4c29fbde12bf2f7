// Scenes built in code for the analytic tests, independent of the JSON loader.
#pragma once
#include "description/scene_description.h"

namespace photon::test {

// A quad as two triangles facing normalize(u x v).
ShapeDescription quad(Vec3 origin, Vec3 u, Vec3 v, uint32_t material, Color emission = Color(0.0f));
ShapeDescription sphere(Vec3 center, float radius, uint32_t material, Color emission = Color(0.0f),
                        bool flipNormals = false);
// The six faces of the box [lo, hi], each facing out, in the order -x, +x, -y, +y, -z, +z,
// bounding the medium `insideMedium` (-1: none).
std::vector<ShapeDescription> boxFaces(Vec3 lo, Vec3 hi, uint32_t material, int32_t insideMedium = -1);
// A point light of intensity I at p, in `medium` (-1: none).
LightDescription pointLight(Vec3 p, Color intensity, int32_t medium = -1);
CameraDescription camera(Vec3 position, Vec3 lookAt, Vec3 up, float fov, int width, int height);
// An orthographic camera (up +y) whose image is viewHeight scene units high.
CameraDescription orthographicCamera(Vec3 position, Vec3 lookAt, float viewHeight, int width, int height);

// A square diffuse plane at y = 0 (half-size `halfSize`) of albedo rho under a point
// light of intensity I at height h above the origin, seen from straight above at height 3
// (fov 50, so the view spans +-1.4 units).
SceneDescription pointLightPlane(float rho, float intensity, float height, int resolution, float halfSize = 20);
// The same plane and camera under `light` alone, rendered with `direct`, `passes` passes and
// `photons` photons a pass.
SceneDescription lightOverPlane(const LightDescription& light, float rho, int resolution, DirectLighting direct,
                                int passes, int64_t photons);

// A scene of no shapes yet, its camera at (0, 0, 5) looking at the origin (it plays no
// part in hit tests), with two materials: 0, grey diffuse; 1, diffuse under a 2x1 texture,
// red for u < 0.5 and blue above, whose lookup shows the uv a hit carried.
SceneDescription hitTestScene();

// One light shape (material 0, grey diffuse) and nothing else, for sampling the light; the
// camera at (0, 3, 3) looking at the origin plays no part.
SceneDescription lightOnly(ShapeDescription light, LightSamplerKind kind = LightSamplerKind::Spatial);

// Camera at the centre of a closed sphere of radius 1, albedo rho, emitting Le inward.
SceneDescription furnace(float rho, float emission, int resolution);

// A ball of radius 1 of `medium` about the origin, bounded by an index-1 sphere, in a sky
// of radiance `sky` (none where black), seen from its centre, the camera in the medium, at
// 16 x 16: 256 passes of 1,000 photons, paths of up to 200 vertices.
SceneDescription ballOfMedium(IntegratorKind kind, MediumDescription medium, Color sky);

// A closed 2 m room of grey walls (albedo 0.6), 1 m high, under `lights` (an environment
// light's come in through the holes of `ceiling`), seen from one corner at 24 x 24: for
// the environment light's sampling (portals, the environment guide).
SceneDescription roomUnder(std::vector<LightDescription> lights, IntegratorKind kind, int passes, uint64_t seed,
                           std::vector<ShapeDescription> ceiling);
// The room's ceiling with a 0.5 m square hole over the middle.
std::vector<ShapeDescription> ceilingWithAHole();


}  // namespace photon::test
