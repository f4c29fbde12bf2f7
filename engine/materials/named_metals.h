// The conductor's named metals (materials/metal_table.h, projected from measured spectra by
// scripts/metal_rgb.py): by chemical symbol, and by pbrt-v4's names of its conductor spectra.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include "materials/material.h"

namespace photon {

// "Au" -> gold's RGB eta and k; nullopt for a symbol not in the table.
std::optional<ComplexIor> findMetal(std::string_view symbol);

// pbrt-v4's named spectra (file format, "Named Spectra"): "metal-Au-eta" -> gold's RGB eta,
// "metal-Au-k" -> its k. Only the metals pbrt-v4 names; nullopt otherwise.
std::optional<Color> findPbrtMetalSpectrum(std::string_view name);

// The accepted names, comma-separated, for error messages.
std::string metalSymbols();
std::string pbrtMetalSpectrumNames();

}  // namespace photon
