#include "import/pbrt/lens_system.h"
#include <cmath>
#include <sstream>

namespace photon::pbrt {

LensFile parseLensFile(const std::string& text) {
    LensFile out;
    std::vector<double> values;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::istringstream words(line.substr(0, line.find('#')));
        std::string word;
        while (words >> word) {
            char* end = nullptr;
            const double v = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0' || !std::isfinite(v)) {
                out.error = "line " + std::to_string(number) + ": \"" + word + "\" is not a number";
                return out;
            }
            values.push_back(v);
        }
    }
    if (values.empty() || values.size() % 4 != 0) {
        out.error = "expected rows of four numbers (radius, thickness, index, aperture diameter in mm), found " +
                    std::to_string(values.size()) + " numbers";
        return out;
    }
    for (size_t i = 0; i < values.size(); i += 4) {
        const LensInterface row{values[i], values[i + 1], values[i + 2], values[i + 3]};
        if (!(row.thickness >= 0) || !(row.eta == 0 || row.eta >= 1) || !(row.apertureDiameter > 0)) {
            out.error = "row " + std::to_string(i / 4 + 1) +
                        ": the thickness must be >= 0, the index 0 (air) or >= 1, the aperture > 0";
            return out;
        }
        out.interfaces.push_back(row);
    }
    return out;
}

std::optional<double> paraxialFocalLength(const std::vector<LensInterface>& interfaces) {
    double y = 1, nu = 0, n = 1;  // height, reduced angle n u, index before the interface
    for (size_t i = 0; i < interfaces.size(); ++i) {
        const LensInterface& s = interfaces[i];
        const double next = s.eta == 0 ? 1.0 : s.eta;
        if (s.radius != 0) nu -= y * (next - n) / s.radius;
        // The last row's thickness is the film's distance, which focusing sets.
        if (i + 1 < interfaces.size()) y += s.thickness * nu / next;
        n = next;
    }
    // The system's power is -n u for y = 1; its effective focal length 1 / power (the
    // distance behind the rear principal plane where it focuses when the film is in air).
    if (!(nu < 0) || !std::isfinite(nu)) return std::nullopt;
    return -1.0 / nu;
}

std::optional<double> apertureStopDiameter(const std::vector<LensInterface>& interfaces) {
    for (const LensInterface& s : interfaces)
        if (s.radius == 0) return s.apertureDiameter;
    return std::nullopt;
}

}  // namespace photon::pbrt
