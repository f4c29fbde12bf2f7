// Checkpoint streams: an integrator's whole state, so a render can stop and resume later
// with the image an uninterrupted render would have made (random streams are keyed by
// pass, so state plus pass count is all there is). Binary, for the machine that wrote it.
#pragma once
#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <vector>
#include "../scene/render_settings.h"

namespace photon {

class CheckpointError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What a checkpoint belongs to: resuming under other settings or another image size
// would silently make a different image, so it is refused instead.
struct CheckpointKey {
    uint32_t width = 0, height = 0;
    uint64_t settings = 0;  // fingerprint of every setting that changes the image
    bool operator==(const CheckpointKey&) const = default;
};
CheckpointKey checkpointKey(const RenderSettings& settings, int width, int height);

void writeCheckpointHeader(std::ostream& out, const CheckpointKey& key);
// Throws CheckpointError if the stream is not a checkpoint or belongs to another key.
void readCheckpointHeader(std::istream& in, const CheckpointKey& expected);

template <class T>
void writeRaw(std::ostream& out, const T* data, size_t count) {
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(sizeof(T) * count));
    if (!out) throw CheckpointError("checkpoint: write failed");
}
template <class T>
void readRaw(std::istream& in, T* data, size_t count) {
    in.read(reinterpret_cast<char*>(data), static_cast<std::streamsize>(sizeof(T) * count));
    if (!in) throw CheckpointError("checkpoint: truncated");
}

}  // namespace photon
