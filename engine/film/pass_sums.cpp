// PassSums: adding batches, and their binary form. The form: "PHPS", a version, the batch's
// first pass, pass count, odd-pass count, width and height (little-endian), then the values
// and the odd passes' luminance as zlib compresses them (film/zlib_block.h). Neighbouring pixels' sums share their high bytes, which is most of what
// zlib finds to squeeze (measured in tests/test_independent_passes.cpp).
#include <photon/pass_sums.h>
#include "film/zlib_block.h"
#include <cstring>
#include <stdexcept>

namespace photon {
namespace {

constexpr char kPassSumsMagic[4] = {'P', 'H', 'P', 'S'};
constexpr uint32_t kPassSumsVersion = 2;

struct PassSumsHeader {
    char magic[4];
    uint32_t version;
    int64_t first, count, oddCount;
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
    if (oddLuminance.size() != other.oddLuminance.size()) throw std::invalid_argument("pass sums without their odd half");
    for (size_t i = 0; i < oddLuminance.size(); ++i)
        if (__builtin_add_overflow(oddLuminance[i], other.oddLuminance[i], &oddLuminance[i]))
            throw std::invalid_argument("pass sums overflow");
    count += other.count;
    oddCount += other.oddCount;
}

std::string PassSums::encode() const {
    PassSumsHeader h{};
    std::memcpy(h.magic, kPassSumsMagic, sizeof kPassSumsMagic);
    h.version = kPassSumsVersion;
    h.first = first, h.count = count, h.oddCount = oddCount, h.width = width, h.height = height;
    std::vector<int64_t> both(values);
    both.insert(both.end(), oddLuminance.begin(), oddLuminance.end());
    return packZlibBlock(std::string_view(reinterpret_cast<const char*>(&h), sizeof h), both.data(),
                         both.size() * sizeof(int64_t));
}

PassSums PassSums::decode(std::string_view bytes) {
    PassSumsHeader h;
    if (bytes.size() < sizeof h) throw std::invalid_argument("pass sums: shorter than their header");
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kPassSumsMagic, sizeof kPassSumsMagic) != 0) throw std::invalid_argument("pass sums: not pass sums");
    if (h.version != kPassSumsVersion)
        throw std::invalid_argument("pass sums: version " + std::to_string(h.version) + ", expected " +
                                    std::to_string(kPassSumsVersion));
    if (h.width <= 0 || h.height <= 0 || int64_t(h.width) * h.height > (int64_t(1) << 28) || h.count <= 0 ||
        h.first < 0 || h.oddCount < 0 || h.oddCount > h.count)
        throw std::invalid_argument("pass sums: invalid size or pass range");
    PassSums s;
    s.first = h.first, s.count = h.count, s.oddCount = h.oddCount, s.width = h.width, s.height = h.height;
    const size_t n = valueCount(h.width, h.height), pixels = n / 3;
    std::vector<int64_t> both(n + pixels);
    if (!unpackZlibBlock(bytes, sizeof h, both.data(), both.size() * sizeof(int64_t)))
        throw std::invalid_argument("pass sums: damaged values");
    s.oddLuminance.assign(both.begin() + std::ptrdiff_t(n), both.end());
    both.resize(n);
    s.values = std::move(both);
    return s;
}

}  // namespace photon
