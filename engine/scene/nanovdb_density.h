// A density grid from a NanoVDB file (.nvdb: pbrt-v4's "nanovdb" medium, and what OpenVDB
// tools export through nanovdb_convert): its float grid of the name asked for, sampled as
// NanoVDB's trilinear sampler does (voxel (i, j, k) at index point (i, j, k)), zero outside
// the box of its active voxels. The grid stays sparse: its samples are read through the
// tree, not copied into an array.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#include "math/density_grid.h"

namespace photon {

// worldFromGrid places the grid's own world space (its voxel size and origin) in the scene.
// Throws std::runtime_error saying what is wrong (no such grid, not a float grid, a codec
// this build cannot read, a damaged file).
std::shared_ptr<const DensityGrid> readNanoVdbDensity(const std::filesystem::path& file, const std::string& gridName,
                                                      const Transform& worldFromGrid);
// Whether the file holds a grid of that name (a "temperature" grid makes pbrt-v4's nanovdb
// medium emit); throws std::runtime_error where it cannot be read as NanoVDB.
bool nanoVdbHasGrid(const std::filesystem::path& file, const std::string& gridName);

}  // namespace photon
