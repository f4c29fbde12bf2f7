#include "accel/radix_sort.h"
#include "accel/overwrite_buffer.h"
#include <tbb/parallel_for.h>
#include <algorithm>
#include <array>

namespace photon {

namespace {
constexpr int kDigitBits = 11;  // at most 2048 counters per piece: they stay in L1
constexpr size_t kDigits = size_t(1) << kDigitBits;
constexpr size_t kPieces = 32;  // fixed, so that the result does not depend on threads
}  // namespace

uint64_t* radixSortByBits(uint64_t* keys, uint64_t* scratch, size_t n, int lowBit, int bitCount) {
    const size_t pieceSize = (n + kPieces - 1) / kPieces;
    std::vector<std::array<uint32_t, kDigits>> counts(kPieces);
    // Equal digits: 18 bits as 9 + 9 scatter to 512 places at a time, not 2048 then 128.
    const int passes = (bitCount + kDigitBits - 1) / kDigitBits;
    const int digitBits = passes == 0 ? 0 : (bitCount + passes - 1) / passes;
    for (int shift = lowBit; shift < lowBit + bitCount; shift += digitBits) {
        const int bits = std::min(digitBits, lowBit + bitCount - shift);
        const uint64_t mask = (uint64_t(1) << bits) - 1;
        auto digit = [&](uint64_t key) { return static_cast<size_t>((key >> shift) & mask); };
        tbb::parallel_for(size_t(0), kPieces, [&](size_t p) {
            counts[p].fill(0);
            for (size_t i = p * pieceSize, end = std::min(n, (p + 1) * pieceSize); i < end; ++i) ++counts[p][digit(keys[i])];
        });
        // Where each piece's keys of each digit start: digit-major, then piece order.
        uint32_t start = 0;
        for (size_t d = 0; d <= mask; ++d)
            for (size_t p = 0; p < kPieces; ++p) {
                uint32_t c = counts[p][d];
                counts[p][d] = start;
                start += c;
            }
        tbb::parallel_for(size_t(0), kPieces, [&](size_t p) {
            for (size_t i = p * pieceSize, end = std::min(n, (p + 1) * pieceSize); i < end; ++i)
                scratch[counts[p][digit(keys[i])]++] = keys[i];
        });
        std::swap(keys, scratch);
    }
    return keys;
}

void radixSortByBits(std::vector<uint64_t>& keys, std::vector<uint64_t>& scratch, int lowBit, int bitCount) {
    resizeForOverwrite(scratch, keys.size());
    if (radixSortByBits(keys.data(), scratch.data(), keys.size(), lowBit, bitCount) != keys.data()) keys.swap(scratch);
}

}  // namespace photon
