#include "integrators/common/checkpoint.h"
#include <zlib.h>
#include <cstring>
#include <type_traits>
#include "math/rng.h"

namespace photon {

namespace {
constexpr char kMagic[8] = {'P', 'H', 'O', 'T', 'O', 'N', 'C', 'K'};
// 2: the key covers every state setting alike (visitStateSettings).
constexpr uint32_t kVersion = 2;

uint64_t mixIn(uint64_t h, uint64_t v) { return mix64(h ^ (v + 0x9e3779b97f4a7c15ull)); }

// A setting's value as bits: floats by their representation, the rest as integers.
template <class T>
uint64_t bits(T value) {
    if constexpr (std::is_same_v<T, float>) {
        uint32_t u;
        std::memcpy(&u, &value, sizeof u);
        return u;
    } else {
        return static_cast<uint64_t>(value);
    }
}
}  // namespace

CheckpointKey checkpointKey(const RenderSettings& s, int width, int height) {
    uint64_t h = 0;
    visitStateSettings(s, [&](auto value) { h = mixIn(h, bits(value)); });
    return {static_cast<uint32_t>(width), static_cast<uint32_t>(height), h};
}

void writeCheckpointHeader(std::ostream& out, const CheckpointKey& key) {
    writeRaw(out, kMagic, sizeof kMagic);
    writeRaw(out, &kVersion, 1);
    writeRaw(out, &key, 1);
}

void readCheckpointHeader(std::istream& in, const CheckpointKey& expected) {
    readCheckpointHeader(in, expected, expected);
}

bool readCheckpointHeader(std::istream& in, const CheckpointKey& first, const CheckpointKey& second) {
    char magic[sizeof kMagic];
    uint32_t version = 0;
    CheckpointKey key;
    readRaw(in, magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw CheckpointError("checkpoint: not a photon checkpoint");
    readRaw(in, &version, 1);
    if (version != kVersion) throw CheckpointError("checkpoint: unsupported version " + std::to_string(version));
    readRaw(in, &key, 1);
    if (key.width != first.width || key.height != first.height)
        throw CheckpointError("checkpoint: made for a " + std::to_string(key.width) + "x" + std::to_string(key.height) +
                              " image");
    if (key.settings != first.settings && key.settings != second.settings)
        throw CheckpointError("checkpoint: made with other render settings");
    return key.settings != first.settings;
}

namespace {
struct Seal {
    uint64_t bodyBytes = 0;
    uint32_t crc = 0;
    uint32_t magic = 0x4c414553;  // "SEAL"
};

uint32_t crc32Of(std::string_view bytes) {
    uLong crc = crc32_z(0L, Z_NULL, 0);
    return static_cast<uint32_t>(crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}
}  // namespace

std::string sealCheckpoint(std::string body) {
    Seal seal{body.size(), crc32Of(body)};
    body.append(reinterpret_cast<const char*>(&seal), sizeof seal);
    return body;
}

std::string_view unsealCheckpoint(std::string_view sealed) {
    Seal seal, expected;
    if (sealed.size() < sizeof seal) throw CheckpointError("checkpoint: truncated");
    std::memcpy(&seal, sealed.data() + sealed.size() - sizeof seal, sizeof seal);
    std::string_view body = sealed.substr(0, sealed.size() - sizeof seal);
    if (seal.magic != expected.magic || seal.bodyBytes != body.size())
        throw CheckpointError("checkpoint: truncated or not a photon checkpoint");
    if (seal.crc != crc32Of(body)) throw CheckpointError("checkpoint: damaged (CRC-32 mismatch)");
    return body;
}

void requireEndOfCheckpoint(std::istream& in) {
    if (in.peek() != std::char_traits<char>::eof()) throw CheckpointError("checkpoint: unexpected bytes at the end");
}

bool readBlockTag(std::istream& in, uint64_t tag) {
    const std::istream::pos_type start = in.tellg();
    uint64_t read = 0;
    if (in.read(reinterpret_cast<char*>(&read), sizeof read) && read == tag) return true;
    in.clear();
    in.seekg(start);
    return false;
}

int readPassCount(std::istream& in) {
    int passes = 0;
    readRaw(in, &passes, 1);
    if (passes < 0) throw CheckpointError("checkpoint: invalid pass count " + std::to_string(passes));
    return passes;
}

}  // namespace photon
