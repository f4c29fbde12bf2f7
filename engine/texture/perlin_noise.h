// Gradient noise and its fractal sums, as pbrt-v4 defines them for its procedural textures
// (Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed., sec. 10.6): Perlin's
// noise (Perlin 2002, "Improving Noise": his permutation table and quintic fade) with
// pbrt's choice of the twelve gradients, so that an imported scene's fbm, wrinkled, windy
// and dots textures show the pattern its author saw in pbrt.
#pragma once
#include <photon/vec.h>

namespace photon {

// Noise in [-1, 1], 0 at every integer lattice point; it repeats every 256 units.
float perlinNoise(Vec3 p);
// Fractional Brownian motion: sum over `octaves` of omega^i noise(1.99^i p).
float fractalBrownianMotion(Vec3 p, float omega, int octaves);
// Turbulence: sum over `octaves` of omega^i |noise(1.99^i p)|, plus 0.2 omega^octaves for
// the octaves left out.
float turbulence(Vec3 p, float omega, int octaves);

}  // namespace photon
