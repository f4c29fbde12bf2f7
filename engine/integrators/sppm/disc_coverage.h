// render.disc_coverage: the share of a gather disc on which photons can land.
//
// A visible point's estimate divides the flux its photons bring by the disc's whole area,
// pi r^2. Where a surface's edge cuts the disc (a room's corner, the foot of a box, a
// table's rim) part of that area holds no surface that faces as the disc does, no photon
// lands there, and the estimate is low by that share. Radii that follow the light shrink
// there instead (adaptive_radius.h), which trades the bias for noise: on the Bitterli
// Cornell box at 64 x 64 the noise sat along the corners.
//
// The share is measured with rays, as the gather counts photons: a photon is gathered if it
// lands inside the disc's sphere on a surface whose normal is within 60 degrees of the
// point's. So K columns through the sphere, along the point's normal, at points spread
// evenly over the disc (a Fibonacci spiral, turned by a random angle each pass), each cast
// from the sphere's top down through it: a column counts where the first surface it meets
// that is not a pure mirror or glass (which photons pass through) faces as the point does,
// and the way to its foot from the centre, just over the surface, does not end inside
// something standing on the disc. A column past a wall starts behind it and meets nothing,
// one past a table's edge finds the floor beyond the sphere; one inside a box on the floor
// would find the floor under it, where no photon comes, but the way there enters the box by
// its side and stays in. The way to the floor behind a post or a table's leg thinner than
// the disc goes in and out again: photons land there from above, and the gather counts them.
// The share is the columns that count over K (weighted by the gather's kernel); its mean
// over the turns is the share of the disc's projection the gather can see. The pass's flux
// is divided by it, and its photons' spread compared with what a flat light over the seen
// part would give (meanSpread), not with 1/2.
//
// Most discs are whole, and measuring every one each pass cost more than it saved (the
// glass-sphere Cornell box at 256², with four outer columns of every disc looked at first:
// 158 passes in 10 s against 225). A disc that an edge cuts shows it by the photons it turns
// away, on a surface facing elsewhere inside its sphere (the other wall of a corner, a box's
// lit side), so only those discs are measured (sppm_bands.cpp). Where no lit surface inside the
// sphere shows the edge (a thin shelf's rim over nothing), the disc is taken whole, as
// without the measurement.
#pragma once
#include <photon/vec.h>
#include "integrators/common/photon_kernel.h"

namespace photon {

class Scene;

struct DiscCoverage {
    float share = 1;         // of the disc's kernel-weighted area, in (0, 1]
    float meanSpread = 0.5f; // mean d^2 / r^2 over the covered part (1/2 for the whole disc)
};

// Columns measured a pass: the share's error on a disc halved by a straight edge is at most
// about 1 / kDiscCoverageColumns, and averages out over the passes' turns.
inline constexpr int kDiscCoverageColumns = 16;

// The coverage of the disc of squared radius r2 about `p` on a surface of normal n (toward
// the viewer); `transmits`: photons from behind count too. `turn` in [0, 1) turns the spiral.
DiscCoverage measureDiscCoverage(const Scene& scene, Vec3 p, Vec3 n, float r2, bool transmits, KernelKind kernel,
                                 float turn);

}  // namespace photon
