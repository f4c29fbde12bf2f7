#include "media/diffusion_dipole.h"
#include <algorithm>
#include <cmath>

namespace photon {

double dipoleDiffuseReflectance(double albedo, double eta) {
    // Jensen et al. 2001, eq. 2: R_d = a'/2 (1 + exp(-4/3 A sqrt(3 (1 - a')))) exp(-sqrt(3 (1 - a'))),
    // A = (1 + F_dr) / (1 - F_dr), F_dr the diffuse Fresnel reflectance (their eq. 8's fit).
    const double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
    const double a = (1 + fdr) / (1 - fdr), s = std::sqrt(3 * (1 - albedo));
    return 0.5 * albedo * (1 + std::exp(-4.0 / 3.0 * a * s)) * std::exp(-s);
}

double albedoOfDiffuseReflectance(double reflectance, double eta) {
    // R_d rises monotonically with the albedo: bisection to double precision.
    double lo = 0, hi = 1;
    if (!(reflectance > dipoleDiffuseReflectance(lo, eta))) return lo;
    if (!(reflectance < dipoleDiffuseReflectance(hi, eta))) return hi;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (dipoleDiffuseReflectance(mid, eta) < reflectance ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

ScatteringCoefficients coefficientsOfReflectance(Color reflectance, Color meanFreePath, double eta) {
    ScatteringCoefficients c;
    for (int i = 0; i < 3; ++i) {
        const double sigmaT = 1 / double(meanFreePath[i]);
        const double albedo = albedoOfDiffuseReflectance(std::clamp<double>(reflectance[i], 0, 1), eta);
        c.scattering[i] = float(albedo * sigmaT);
        c.absorption[i] = float((1 - albedo) * sigmaT);
    }
    return c;
}

}  // namespace photon
