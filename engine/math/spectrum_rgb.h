// Spectra as the linear sRGB colours photon renders with: CIE 1931 colour matching functions
// (Wyman, Sloan & Shirley 2013's analytic fit) under the equal-energy illuminant, XYZ to sRGB
// (IEC 61966-2-1), white-balanced so that a constant spectrum stays grey.
#pragma once
#include <vector>
#include <photon/vec.h>

namespace photon {

// A sampled spectrum (wavelengths in nm, ascending, with values), linear between the
// samples and held constant past the table's ends. Linear in the values, so a table of
// spectra on one set of wavelengths projects as a sum of per-wavelength colours
// (spectrumWeights).
Color projectSpectrum(const std::vector<double>& wavelengths, const std::vector<double>& values);

// The colour each sample of a spectrum on `wavelengths` contributes per unit value:
// projectSpectrum(wavelengths, values) == sum of values[i] * weights[i].
std::vector<Color> spectrumWeights(const std::vector<double>& wavelengths);

// Planck's law at `kelvin`, projected as above and scaled to unit luminance.
Color blackbodyColor(double kelvin);
// Planck's law at `kelvin` over its value at the peak wavelength, projected as above: pbrt-v4's
// BlackbodySpectrum, which its media emit by temperature, unscaled.
Color blackbodyPeakColor(double kelvin);

}  // namespace photon
