// NanoVDB's reader with its two codecs: ZIP (zlib) and Blosc, which pbrt-v4's scene files use.
#define NANOVDB_USE_ZIP
#define NANOVDB_USE_BLOSC
#include "scene/nanovdb_density.h"
#include <algorithm>
#include <stdexcept>
#include <iostream>  // GridValidator.h uses std::cerr without including it
#include <nanovdb/util/GridValidator.h>
#include <nanovdb/util/IO.h>

namespace photon {

namespace {
// At most 8 GiB of grid, and at most 256 times the file's bytes (a codec's ratio) beyond
// 64 MiB: a grid of a few voxels holds half a megabyte of internal nodes, which Blosc
// writes in 1.3 KB (tests/test_nanovdb_density.cpp).
constexpr uintmax_t kMaxGridBytes = uintmax_t(8) << 30, kMaxInflation = 256, kAlwaysRead = uintmax_t(64) << 20;

class NanoVdbSamples final : public DensityGrid::Samples {
public:
    NanoVdbSamples(nanovdb::GridHandle<> handle, const nanovdb::FloatGrid& grid)
        : handle_(std::move(handle)), grid_(grid), min_(grid.indexBBox().min()) {}
    void corners(int i, int j, int k, const int n[3], float c[8]) const override {
        // An accessor of its own for each cell (the walk along a ray runs on many threads),
        // whose cache serves the corners after the first.
        const auto acc = grid_.getAccessor();
        for (int corner = 0; corner < 8; ++corner) {
            const int x = i + (corner & 1), y = j + ((corner >> 1) & 1), z = k + (corner >> 2);
            const bool inside = x >= 0 && y >= 0 && z >= 0 && x < n[0] && y < n[1] && z < n[2];
            c[corner] = inside ? std::max(acc.getValue(min_ + nanovdb::Coord(x, y, z)), 0.0f) : 0.0f;
        }
    }

private:
    nanovdb::GridHandle<> handle_;  // owns the grid's memory
    const nanovdb::FloatGrid& grid_;
    nanovdb::Coord min_;
};

// The file's grids, from their headers.
std::vector<nanovdb::io::GridMetaData> gridsOf(const std::filesystem::path& file) {
    try {
        return nanovdb::io::readGridMetaData(file.string());
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("cannot read it as NanoVDB: ") + e.what());
    }
}
}  // namespace

bool nanoVdbHasGrid(const std::filesystem::path& file, const std::string& gridName) {
    const std::vector<nanovdb::io::GridMetaData> grids = gridsOf(file);
    return std::any_of(grids.begin(), grids.end(), [&](const auto& g) { return g.gridName == gridName; });
}

std::shared_ptr<const DensityGrid> readNanoVdbDensity(const std::filesystem::path& file, const std::string& gridName,
                                                      const Transform& worldFromGrid) {
    // The grid's size from its header, checked before anything is allocated: a scene sent to
    // the server must not make it hold more than its file could plausibly inflate to.
    const std::vector<nanovdb::io::GridMetaData> grids = gridsOf(file);
    const auto meta = std::find_if(grids.begin(), grids.end(), [&](const auto& g) { return g.gridName == gridName; });
    if (meta == grids.end()) throw std::runtime_error("holds no grid named \"" + gridName + "\"");
    if (meta->gridType != nanovdb::GridType::Float) throw std::runtime_error("its grid \"" + gridName + "\" does not hold floats");
    std::error_code error;
    const uintmax_t fileBytes = std::filesystem::file_size(file, error);
    if (error || meta->gridSize > kMaxGridBytes || meta->gridSize > std::max(kMaxInflation * fileBytes, kAlwaysRead))
        throw std::runtime_error("its grid \"" + gridName + "\" claims " + std::to_string(meta->gridSize) +
                                 " bytes, more than photon reads from a file of " + std::to_string(fileBytes));
    nanovdb::GridHandle<> handle;
    try {
        handle = nanovdb::io::readGrid(file.string(), gridName);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("cannot read it as NanoVDB: ") + e.what());
    }
    const nanovdb::FloatGrid* grid = handle ? handle.grid<float>() : nullptr;
    if (!grid) throw std::runtime_error("cannot read its grid \"" + gridName + "\"");
    // Its nodes are offsets into the buffer: a damaged file is refused before one is followed.
    if (const std::string why = nanovdb::GridValidator<float>::check(*grid, true); !why.empty())
        throw std::runtime_error("its grid \"" + gridName + "\" is damaged: " + why);
    const nanovdb::CoordBBox box = grid->indexBBox();
    if (box.empty()) throw std::runtime_error("its grid \"" + gridName + "\" has no active voxels");
    const nanovdb::Coord dim = box.dim();
    // Lattice (i, j, k) is index min + (i, j, k); index = InvMat (p - Vec) of a point of the
    // grid's world (nanovdb::Map::applyInverseMapF).
    const nanovdb::Map& map = grid->map();
    const float* inv = map.mInvMatF;
    const Vec3 vec{map.mVecF[0], map.mVecF[1], map.mVecF[2]};
    Transform latticeFromGrid{{inv[0], inv[1], inv[2], 0, inv[3], inv[4], inv[5], 0, inv[6], inv[7], inv[8], 0}};
    const Vec3 shift = latticeFromGrid.vector(vec);
    const Vec3 min{static_cast<float>(box.min()[0]), static_cast<float>(box.min()[1]), static_cast<float>(box.min()[2])};
    latticeFromGrid.m[3] = -shift.x - min.x, latticeFromGrid.m[7] = -shift.y - min.y, latticeFromGrid.m[11] = -shift.z - min.z;
    // The tree's statistics bound the values; a file written without them is taken to scatter.
    const float maxValue = grid->tree().root().maximum();
    const float bound = maxValue > 0 ? maxValue : 1.0f;
    auto samples = std::make_shared<const NanoVdbSamples>(std::move(handle), *grid);
    return std::make_shared<const DensityGrid>(dim[0], dim[1], dim[2], std::move(samples), bound,
                                               latticeFromGrid * worldFromGrid.inverse());
}

}  // namespace photon
