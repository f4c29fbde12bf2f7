#include "import/pbrt/pbrt_spectra.h"
#include <cmath>
#include <fstream>
#include <sstream>
#include <photon/errors.h>
#include "import/pbrt/pbrt_params.h"
#include "math/spectrum_rgb.h"
#include "materials/named_metals.h"
#include "scene/scene_paths.h"

namespace photon::pbrt {

namespace {

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
