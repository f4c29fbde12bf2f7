// pbrt-v4's procedural "cloud" medium (its CloudMedium): a density made of gradient noise
// (texture/perlin_noise.h), five octaves summed at a base frequency, the lookup point
// perturbed by the noise's own gradient for wisps, fading with height:
//   d = clamp((1 - y) 4.5 density fbm(p'), 0, 1) + 2 max(0, 0.5 - y), clamped to [0, 1],
// in the medium's own space, inside its box. photon's media integrate their density exactly
// along a ray when it is trilinear between samples (math/density_grid.h), so the cloud is
// sampled on such a grid when the scene loads, fine enough for its first four octaves.
#pragma once
#include <array>
#include <vector>
#include <photon/vec.h>

namespace photon {

struct CloudParameters {
    float density = 1;    // scales the noise before the clamp
    float wispiness = 1;  // the perturbation's strength; 0 for none
    float frequency = 5;  // the base octave's frequency in the medium's units
};

// The density at p, in the medium's space (pbrt-v4's CloudMedium::Density).
float cloudDensity(Vec3 p, const CloudParameters& cloud);

// Samples a side that resolve the fourth octave (frequency * 1.99^3) with four samples a
// period over `extent`, between 8 and 256.
int cloudResolution(const CloudParameters& cloud, float extent);

// The density at the centres of the n[0] x n[1] x n[2] cells of the box [p0, p1], x fastest
// (math/density_grid.h's order), computed on the render's threads.
std::vector<float> sampleCloud(const CloudParameters& cloud, const std::array<int, 3>& n, Vec3 p0, Vec3 p1);

}  // namespace photon
