// PassSums: adding batches, and their binary form. The form: "PHPS", a version, the batch's
// first pass, pass count, width and height (little-endian), then the values as zlib
// compresses them (film/zlib_block.h). Neighbouring pixels' sums share their high bytes, which is most of what
// zlib finds to squeeze (measured in tests/test_independent_passes.cpp).
#include <photon/pass_sums.h>
#include "film/zlib_block.h"
#include <cstring>
#include <stdexcept>

namespace photon {
namespace {

constexpr char kMagic[4] = {'P', 'H', 'P', 'S'};
constexpr uint32_t kVersion = 1;

struct Header {
    char magic[4];
    uint32_t version;
    int64_t first, count;
    int32_t width, height;
};

size_t valueCount(int64_t width, int64_t height) { return size_t(width) * size_t(height) * 3; }

}  // namespace

void PassSums::add(const PassSums& other) {
    if (other.width != width || other.height != height)
        throw std::invalid_argument("pass sums of " + std::to_string(other.width) + "x" +
                                    std::to_string(other.height) + " added to " + std::to_string(width) + "x" +
                                    std::to_string(height));
    for (size_t i = 0; i < values.size(); ++i)
        if (__builtin_add_overflow(values[i], other.values[i], &values[i]))
            throw std::invalid_argument("pass sums overflow");
    count += other.count;
}

std::string PassSums::encode() const {
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = kVersion;
    h.first = first, h.count = count, h.width = width, h.height = height;
    return packZlibBlock(std::string_view(reinterpret_cast<const char*>(&h), sizeof h), values.data(),
                         values.size() * sizeof(int64_t));
}

PassSums PassSums::decode(std::string_view bytes) {
    Header h;
    if (bytes.size() < sizeof h) throw std::invalid_argument("pass sums: shorter than their header");
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) throw std::invalid_argument("pass sums: not pass sums");
    if (h.version != kVersion)
        throw std::invalid_argument("pass sums: version " + std::to_string(h.version) + ", expected " +
                                    std::to_string(kVersion));
    if (h.width <= 0 || h.height <= 0 || int64_t(h.width) * h.height > (int64_t(1) << 28) || h.count <= 0 ||
        h.first < 0)
        throw std::invalid_argument("pass sums: invalid size or pass range");
    PassSums s;
    s.first = h.first, s.count = h.count, s.width = h.width, s.height = h.height;
    s.values.resize(valueCount(h.width, h.height));
    if (!unpackZlibBlock(bytes, sizeof h, s.values.data(), s.values.size() * sizeof(int64_t)))
        throw std::invalid_argument("pass sums: damaged values");
    return s;
}

}  // namespace photon
