#include "integrators/sppm/camera_paths.h"
#include "integrators/common/checkpoint.h"

namespace photon {

namespace {
// Marks the block in a checkpoint: no pass count of the halves that may follow instead
// (PassHalves, an int64 below 2^31) can equal it.
constexpr uint64_t kCameraPathsTag = 0x534854415041434dull;  // "MCAPATHS"
}  // namespace

void AdaptiveCameraPaths::save(std::ostream& out) const {
    writeRaw(out, &kCameraPathsTag, 1);
    writeRaw(out, &scale_, 1);
    writeRaw(out, pixels_.data(), pixels_.size());
}

bool AdaptiveCameraPaths::restoreBlock(std::istream& in, int64_t renderPasses) {
    if (!readBlockTag(in, kCameraPathsTag)) return false;
    float scale = 0;
    readRaw(in, &scale, 1);
    if (!(scale >= 0) || !std::isfinite(scale)) throw CheckpointError("checkpoint: invalid camera path counts");
    std::vector<Pixel> pixels(pixels_.size());
    readRaw(in, pixels.data(), pixels.size());
    // At least one path a pass, at most kMaxPaths.
    const double least = static_cast<double>(renderPasses), most = least * kMaxPaths;
    for (const Pixel& p : pixels)
        if (!(p.paths >= least && p.paths <= most) || !(p.squares >= 0) || !std::isfinite(p.squares))
            throw CheckpointError("checkpoint: invalid camera path counts");
    scale_ = scale;
    pixels_ = std::move(pixels);
    return true;
}

}  // namespace photon
