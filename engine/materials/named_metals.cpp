#include "materials/named_metals.h"
#include "materials/metal_table.h"

namespace photon {

std::optional<ComplexIor> findMetal(std::string_view symbol) {
    for (const MetalIor& m : kMetalIors)
        if (m.name == symbol) return ComplexIor{m.eta, m.k};
    return std::nullopt;
}

std::optional<Color> findPbrtMetalSpectrum(std::string_view name) {
    for (const MetalIor& m : kMetalIors) {
        if (!m.pbrtNamed) continue;
        std::string stem = "metal-" + std::string(m.name);
        if (name == stem + "-eta") return m.eta;
        if (name == stem + "-k") return m.k;
    }
    return std::nullopt;
}

std::string metalSymbols() {
    std::string names;
    for (const MetalIor& m : kMetalIors) names += (names.empty() ? "" : ", ") + std::string(m.name);
    return names;
}

std::string pbrtMetalSpectrumNames() {
    std::string names;
    for (const MetalIor& m : kMetalIors) {
        if (!m.pbrtNamed) continue;
        std::string stem = "metal-" + std::string(m.name);
        names += (names.empty() ? "" : ", ") + stem + "-eta, " + stem + "-k";
    }
    return names;
}

}  // namespace photon
