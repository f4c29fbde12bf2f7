// Checkpoint streams: an integrator's whole state, so a render can stop and resume later
// with the image an uninterrupted render would have made (random streams are keyed by
// pass, so state plus pass count is all there is). Binary, for the machine that wrote it.
#pragma once
#include <cstdint>
#include <istream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <photon/errors.h>
#include <photon/render_settings.h>
#include <photon/vec.h>

namespace photon {

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
// The same for a state that may have been written under either of two keys: returns
// whether it was `second`.
bool readCheckpointHeader(std::istream& in, const CheckpointKey& first, const CheckpointKey& second);

// A whole checkpoint ends in a seal: the length and CRC-32 of everything before it. A file
// cut short or damaged on disk is told from a good one before any of it is used.
std::string sealCheckpoint(std::string body);
// The body of a sealed checkpoint; throws CheckpointError if the seal does not match.
std::string_view unsealCheckpoint(std::string_view sealed);

// An input stream over bytes held elsewhere (C++20 has no ispanstream): a restore reads a
// checkpoint's body where it lies instead of copying it (checkpoints of large images are
// hundreds of megabytes).
struct ViewBuffer : std::streambuf {
    explicit ViewBuffer(std::string_view bytes) {
        char* begin = const_cast<char*>(bytes.data());  // read only: no put area is set
        setg(begin, begin, begin + bytes.size());
    }
    // tellg and seekg, for blocks a restore recognises by a tag it reads ahead.
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
        const off_type from = dir == std::ios_base::beg ? 0 : dir == std::ios_base::cur ? gptr() - eback() : egptr() - eback();
        const off_type to = from + off;
        if (to < 0 || to > egptr() - eback()) return pos_type(off_type(-1));
        setg(eback(), eback() + to, egptr());
        return pos_type(to);
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
        return seekoff(off_type(pos), std::ios_base::beg, which);
    }
};
// The buffer is a base listed first, so it exists before the stream is handed it.
class ViewInputStream : private ViewBuffer, public std::istream {
public:
    explicit ViewInputStream(std::string_view bytes) : ViewBuffer(bytes), std::istream(this) {}
};

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

// Optional blocks (written by later builds than some checkpoints) start with a tag: true,
// past the tag, if the stream is at `tag`; else false, the stream where it was.
bool readBlockTag(std::istream& in, uint64_t tag);
// Reads a count of finished passes, which cannot be negative.
int readPassCount(std::istream& in);
// Throws CheckpointError unless everything has been read: restores call it before they
// change any state, so that they take all of a checkpoint or nothing.
void requireEndOfCheckpoint(std::istream& in);
// What accumulated light, photon counts and radii can be: finite and >= 0. Restores check
// every value, so a damaged checkpoint that slipped past its seal cannot poison a render.
inline bool isFiniteNonNegative(float v) { return v >= 0 && v <= std::numeric_limits<float>::max(); }
inline bool isFiniteNonNegative(Color c) {
    return isFiniteNonNegative(c.x) && isFiniteNonNegative(c.y) && isFiniteNonNegative(c.z);
}

}  // namespace photon
