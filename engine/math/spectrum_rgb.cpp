#include "math/spectrum_rgb.h"
#include <array>
#include <cmath>
#include <functional>

namespace photon {

namespace {

// The asymmetric Gaussian lobe of Wyman, Sloan & Shirley 2013, eq. 1.
double lobe(double x, double mu, double below, double above) {
    const double t = (x - mu) / (x < mu ? below : above);
    return std::exp(-0.5 * t * t);
}

// CIE 1931 2-degree colour matching functions, multi-lobe fit (Wyman et al. 2013, eq. 2).
std::array<double, 3> cie1931(double l) {
    return {1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2),
            0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
            1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)};
}

constexpr int kLambdaMin = 360, kLambdaMax = 830;

// Linear sRGB of a spectrum given per nanometre, before the white balance.
std::array<double, 3> unbalanced(const std::function<double(double)>& s) {
    double xyz[3] = {0, 0, 0}, yIntegral = 0;
    for (int l = kLambdaMin; l <= kLambdaMax; ++l) {
        const auto c = cie1931(l);
        const double v = s(l);
        for (int i = 0; i < 3; ++i) xyz[i] += v * c[i];
        yIntegral += c[1];
    }
    for (double& v : xyz) v /= yIntegral;
    // XYZ -> linear sRGB (IEC 61966-2-1).
    return {3.2406 * xyz[0] - 1.5372 * xyz[1] - 0.4986 * xyz[2], -0.9689 * xyz[0] + 1.8758 * xyz[1] + 0.0415 * xyz[2],
            0.0557 * xyz[0] - 0.2040 * xyz[1] + 1.0570 * xyz[2]};
}

Color balanced(const std::function<double(double)>& s) {
    static const std::array<double, 3> white = unbalanced([](double) { return 1.0; });
    const auto c = unbalanced(s);
    return {float(c[0] / white[0]), float(c[1] / white[1]), float(c[2] / white[2])};
}

}  // namespace

Color projectSpectrum(const std::vector<double>& wavelengths, const std::vector<double>& values) {
    return balanced([&](double l) {
        if (l <= wavelengths.front()) return values.front();
        if (l >= wavelengths.back()) return values.back();
        size_t i = 1;
        while (wavelengths[i] < l) ++i;
        const double t = (l - wavelengths[i - 1]) / (wavelengths[i] - wavelengths[i - 1]);
        return values[i - 1] + t * (values[i] - values[i - 1]);
    });
}

std::vector<Color> spectrumWeights(const std::vector<double>& wavelengths) {
    std::vector<Color> weights;
    std::vector<double> unit(wavelengths.size(), 0.0);
    for (size_t i = 0; i < wavelengths.size(); ++i) {
        unit[i] = 1;
        weights.push_back(projectSpectrum(wavelengths, unit));
        unit[i] = 0;
    }
    return weights;
}

namespace {
// Planck's law at `kelvin` over the spectrum's value at its peak (Wien's displacement law,
// lambda_max = 2.8977721e-3 m K / T): pbrt-v4's BlackbodySpectrum.
double planckOverPeak(double nm, double kelvin) {
    const double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
    auto planck = [&](double l) { return 1 / (std::pow(l, 5) * (std::exp((h * c) / (l * kb * kelvin)) - 1)); };
    return planck(nm * 1e-9) / planck(2.8977721e-3 / kelvin);
}
}  // namespace

Color blackbodyColor(double kelvin) {
    const Color rgb = blackbodyPeakColor(kelvin);
    return rgb / luminance(rgb);
}

Color blackbodyPeakColor(double kelvin) {
    return balanced([&](double nm) { return planckOverPeak(nm, kelvin); });
}

}  // namespace photon
