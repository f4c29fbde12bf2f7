// Light from point, spot and area lights scattered toward the camera along a camera path's
// ray through a medium that scatters, by two strategies weighed against each other (the
// power heuristic, Veach 1997 ch. 9): the light sample where the ray's free flight scatters
// (sampleDirectLightInMedium), which finds the light where the medium is dense, and a light
// of Scene::lightsAlongRays with a point of the segment drawn by equiangular distances
// toward it (media/equiangular.h, Kulla & Fajardo 2012), which finds it where the light is
// near: toward a point light, or toward a point drawn by area on an area light. Near a small
// light the first alone has 1 / r^2 in its weights and heavy tails. Where the path goes on
// from the point it scatters at, the phase function's direction may meet an area light too:
// that is weighed against the light sample there (as at a surface), and the two strategies
// above share the light sample's part.
#pragma once
#include <photon/vec.h>
#include "lights/light.h"
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
    bool continues = true;     // a point it scatters at traces the phase function's direction for light
    float choiceTotal = 0;     // what sampleLightAlongRay's choice of light weighed in all
};

// Light scattered toward the camera from one point of the segment in `medium`, drawn by
// equiangular distances toward a light picked among Scene::lightsAlongRays by what it could
// bring along the segment (light_along_ray.cpp: SegmentLightChoice), with
// the weight against the light sample the path takes where its flight scatters. `beta` is
// the path's throughput where the segment starts. Its draws: the light, the distance, and
// the point on an area light (uPoint). It keeps its choice's total in the segment.
Color sampleLightAlongRay(const Scene& scene, FlightSegment& segment, int32_t medium, Color beta, float uLight,
                          float uDistance, Vec2 uPoint);

// The weight of the light sample ls toward light `light` (its index in Scene::lights) at the
// point where the segment's flight scattered: against the equiangular samples of the
// segment where light was sampled along it, else 1.
float weightAgainstLightAlongRay(const Scene& scene, const FlightSegment& segment, int32_t medium, size_t light,
                                 const LightSample& ls);

}  // namespace photon
