#include "import/pbrt/lens_system.h"
#include "camera/lens_system.h"
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
        if (auto why = lensInterfaceError(row)) {
            out.error = "row " + std::to_string(i / 4 + 1) + ": " + *why;
            return out;
        }
        out.interfaces.push_back(row);
    }
    return out;
}

}  // namespace photon::pbrt
