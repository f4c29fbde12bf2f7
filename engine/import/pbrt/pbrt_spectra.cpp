#include "import/pbrt/pbrt_spectra.h"
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <photon/errors.h>
#include "import/pbrt/pbrt_params.h"
#include "materials/named_metals.h"
#include "scene/scene_paths.h"

namespace photon::pbrt {

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

Color unitLuminance(Color c, const Location& where) {
    const float y = luminance(c);
    if (!(y > 0)) fail(where, "the spectrum has no visible light");
    return c / y;
}

// pbrt-v4's named dielectric spectra as one index each (at 587.6 nm, the d line), since
// photon's dielectric has no dispersion.
std::optional<float> glassIndex(const std::string& name) {
    static const std::pair<const char*, float> kGlasses[] = {
        {"glass-BK7", 1.5168f},  {"glass-BAF10", 1.6700f}, {"glass-FK51A", 1.4866f}, {"glass-LASF9", 1.8503f},
        {"glass-F5", 1.6034f},   {"glass-F10", 1.6200f},   {"glass-F11", 1.6209f},   {"fused-silica", 1.4585f}};
    for (const auto& [n, eta] : kGlasses)
        if (name == n) return eta;
    return std::nullopt;
}

Color namedSpectrum(const Param& p, const std::string& name, SpectrumKind kind) {
    if (auto metal = findPbrtMetalSpectrum(name)) return *metal;
    if (auto eta = glassIndex(name)) return Color(*eta);
    // Illuminants: D65 is the sRGB white, and E the white this projection balances to.
    if (name == "stdillum-D65" || name == "stdillum-E" || name == "illum-acesD60") return Color(1.0f);
    if (name == "stdillum-A") return blackbodyColor(2856);
    fail(p.where, "unknown named spectrum \"" + name + "\" (photon knows " + pbrtMetalSpectrumNames() +
                      ", glass-BK7, glass-BAF10, glass-FK51A, glass-LASF9, glass-F5, glass-F10, glass-F11, "
                      "fused-silica, stdillum-D65, stdillum-E, stdillum-A)");
    (void)kind;
}

// A spectrum file: whitespace-separated (wavelength, value) pairs, '#' comments.
std::vector<double> readSpectrumFile(const Param& p, const std::string& name, const std::filesystem::path& baseDir) {
    if (auto why = checkRelativePath(name)) fail(p.where, "spectrum file \"" + name + "\": " + *why);
    const std::filesystem::path file = baseDir / name;
    std::ifstream in(file);
    if (!in || !isInsideFolder(file, baseDir)) fail(p.where, "spectrum file not found: " + name);
    std::vector<double> values;
    std::string line;
    while (std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        double v;
        while (words >> v) values.push_back(v);
        if (!words.eof()) fail(p.where, "spectrum file " + name + ": not a number in \"" + line + "\"");
    }
    return values;
}

Color sampledSpectrum(const Param& p, const std::vector<double>& pairs) {
    if (pairs.size() < 2 || pairs.size() % 2 != 0)
        fail(p.where, "spectrum \"" + p.name + "\" needs (wavelength, value) pairs");
    std::vector<double> wavelengths, values;
    for (size_t i = 0; i < pairs.size(); i += 2) {
        if (!wavelengths.empty() && !(pairs[i] > wavelengths.back()))
            fail(p.where, "spectrum \"" + p.name + "\": wavelengths must increase");
        wavelengths.push_back(pairs[i]);
        values.push_back(pairs[i + 1]);
    }
    return projectSpectrum(wavelengths, values);
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

Color blackbodyColor(double kelvin) {
    // Planck's law; the constant factors go with the normalisation.
    const double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
    Color rgb = balanced([&](double nm) {
        const double l = nm * 1e-9;
        return (2 * h * c * c) / (std::pow(l, 5) * (std::exp((h * c) / (l * kb * kelvin)) - 1)) * 1e-13;
    });
    return rgb / luminance(rgb);
}

Color spectrumColor(const Param& p, SpectrumKind kind, const std::filesystem::path& baseDir) {
    const auto count = p.numbers.size() + p.strings.size();
    if (p.type == "rgb" || p.type == "color") {
        if (p.numbers.size() != 3) fail(p.where, "\"" + p.name + "\" needs 3 numbers");
        return {float(p.numbers[0]), float(p.numbers[1]), float(p.numbers[2])};
    }
    if (p.type == "float" || p.type == "integer") {
        if (p.numbers.size() != 1) fail(p.where, "\"" + p.name + "\" needs 1 number");
        return Color(float(p.numbers[0]));
    }
    if (p.type == "blackbody") {
        if (p.numbers.size() != 1 || !(p.numbers[0] > 0)) fail(p.where, "\"" + p.name + "\" needs one temperature > 0");
        return blackbodyColor(p.numbers[0]);
    }
    if (p.type != "spectrum") fail(p.where, "\"" + p.name + "\" must be a colour (rgb, spectrum or blackbody), not " + p.type);
    if (count == 0) fail(p.where, "\"" + p.name + "\" has no value");
    Color c;
    if (!p.strings.empty()) {
        const std::string& name = p.strings[0];
        const bool file = name.size() > 4 && name.substr(name.size() - 4) == ".spd";
        if (!file) return namedSpectrum(p, name, kind);  // named spectra are used as pbrt-v4 defines them
        c = sampledSpectrum(p, readSpectrumFile(p, name, baseDir));
    } else if (p.numbers.size() == 1) {
        return Color(float(p.numbers[0]));
    } else {
        c = sampledSpectrum(p, p.numbers);
    }
    return kind == SpectrumKind::Illuminant ? unitLuminance(c, p.where) : c;
}

}  // namespace photon::pbrt
