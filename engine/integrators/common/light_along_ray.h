// Light from point and spot lights scattered toward the camera along a camera path's ray
// through a medium that scatters, by two strategies weighed against each other (the power
// heuristic, Veach 1997 ch. 9): the light sample where the ray's free flight scatters
// (sampleDirectLightInMedium), which finds the light where the medium is dense, and a light
// of Scene::lightsAlongRays with a point of the segment drawn by equiangular distances
// toward it (media/equiangular.h, Kulla & Fajardo 2012), which finds it where the light is
// near. Near a point light the first alone has 1 / r^2 in its weights and heavy tails.
#pragma once
#include <photon/vec.h>
#include "scene/scene.h"

namespace photon {

// A camera path's segment through a medium that scatters, on which its free flight was
// drawn.
struct FlightSegment {
    Vec3 o, d;                 // the ray, |d| = 1
    float end = 0;             // where the segment ends (infinite: the ray leaves the scene)
    Color ratios{1.0f};        // the path's chromatic ratios before the flight (ChromaticFlight)
    float scatteredAt = 0;     // where the flight scattered, if it did
    bool lightSampled = false; // light was sampled along it (sampleLightAlongRay)
};

// Light scattered toward the camera from one point of the segment in `medium`, drawn by
// equiangular distances toward a light picked among Scene::lightsAlongRays by what it could
// bring along the segment (light_along_ray.cpp: SegmentLightChoice), with
// the weight against the light sample the path takes where its flight scatters. `beta` is
// the path's throughput where the segment starts. Its draws: the light and the distance.
Color sampleLightAlongRay(const Scene& scene, const FlightSegment& segment, int32_t medium, Color beta, float uLight,
                          float uDistance);

// The weight of the light sample toward light `light` (its index in Scene::lights) arriving
// along wi at the point where the segment's flight scattered: against the equiangular
// samples of the segment where light was sampled along it, else 1.
float weightAgainstLightAlongRay(const Scene& scene, const FlightSegment& segment, int32_t medium, size_t light,
                                 Vec3 wi);

}  // namespace photon
