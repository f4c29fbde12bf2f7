// Measured BRDFs from RGL's ".bsdf" files (scene/tensor_file.h), as pbrt-v4's "measured"
// material reads them: fields theta_i and phi_i (the outgoing directions measured), ndf and
// sigma (2D), vndf and luminance (phi_i x theta_i x n x n), and the reflectance as "spectra"
// (phi_i x theta_i x wavelengths x n x n, with "wavelengths" in nm), projected to linear
// sRGB once (math/spectrum_rgb.h), or as "rgb" (phi_i x theta_i x 3 x n x n).
#pragma once
#include <memory>
#include <string>
#include "materials/measured_brdf.h"
#include "scene/tensor_file.h"

namespace photon {

// Throws std::runtime_error ("<file>: ...") naming the first field whose type, rank or shape
// does not fit, or whose values are not finite.
std::shared_ptr<const MeasuredBrdf> readMeasuredBrdf(const TensorFile& file);

}  // namespace photon
