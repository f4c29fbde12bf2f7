// A measured isotropic or anisotropic BRDF in the parameterisation of Dupuy & Jakob 2018
// ("An Adaptive Parameterization for Efficient Material Acquisition and Rendering"), as RGL's
// material database publishes them and pbrt-v4's "measured" material and Mitsuba's
// "measured" plugin read them (scene/measured_brdf_file.h reads the files):
//   f(wo, wi) = R(u; wo) D(wm) / (4 sigma(wo) cos theta_i),
// with wm the half vector, D the microfacet normals' density, sigma(wo) their area projected
// toward wo, and R the measured reflectance, tabulated over the unit square u that the
// visible normals' warp (vndf) maps onto the half vectors. Angles are stored as
// u = sqrt(theta / (pi / 2)) and v = (phi + pi) / (2 pi).
#pragma once
#include <memory>
#include "materials/material.h"
#include "math/bilinear_warp.h"

namespace photon {

struct MeasuredBrdf {
    BilinearTable<float> ndf;    // D over (u(theta_m), v(phi_m))
    BilinearTable<float> sigma;  // sigma over (u(theta_o), v(phi_o))
    // The outgoing direction's (phi_o, theta_o) at which the tables below were measured.
    SliceAxes outgoing;
    // Half vectors distributed as the normals visible from wo, over (u(theta_m), v(phi_m)),
    // v relative to phi_o for an isotropic BRDF; and the luminance of R over the warp's
    // input, by which sampling picks that input first.
    BilinearWarp2D vndf, luminance;
    BilinearTable<Color> reflectance;  // R, linear sRGB, over the vndf's input
    bool isotropic = true;
};

// The material of a measured BRDF: a glossy reflection, the same seen from either side.
MaterialPtr makeMeasured(std::shared_ptr<const MeasuredBrdf> brdf);

}  // namespace photon
