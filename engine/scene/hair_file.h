// Cem Yuksel's HAIR file format (cyHairFile, www.cemyuksel.com/research/hairmodels): a
// 128-byte header, then per strand its segment count and per point its position and
// thickness. Tungsten's and Bitterli's hair scenes use it; photon-convert writes imported
// pbrt curves as such files, with the scene naming the basis that joins the points.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include "description/curve_set.h"

namespace photon {

// Strands and points beyond which a file is refused before anything is allocated for them:
// 16M points hold 256 MiB as curve control points.
constexpr size_t kMaxCurvePoints = 16'000'000;

// The strands of a HAIR file, radius = thickness / 2 (the file's default thickness where it
// has no per-point array, else `defaultWidth`); the basis and profile are left as given by
// the caller. Transparency and colour arrays are read past. Throws std::runtime_error
// ("HAIR: <name>: ...") naming the first problem: signature, counts against the file's
// size, a count of points that does not match the strands', a value that is not finite.
CurveSet readHairFile(std::string_view bytes, const std::string& name, float defaultWidth);
CurveSet readHairFile(const std::filesystem::path& file, float defaultWidth);

// The strands as a HAIR file with segment, point and thickness arrays (little-endian).
// Throws std::runtime_error if a strand has more than 65536 points (the format's 16-bit
// segment count) or the bytes cannot be written.
std::string hairFileBytes(const CurveSet& curves);
void writeHairFile(const CurveSet& curves, const std::filesystem::path& file);

}  // namespace photon
