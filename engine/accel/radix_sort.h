// Stable least-significant-digit radix sort of 64-bit keys by a range of their bits, in
// parallel with oneTBB and deterministic: the array is cut into a fixed number of pieces
// whatever the thread count, each piece's digits are counted, and every key goes to a
// position that depends only on the keys (Knuth, TAOCP vol. 3, sec. 5.2.5).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace photon {

// Sorts the n keys at `keys` by bits [lowBit, lowBit + bitCount); keys equal there keep
// their order. `scratch` has room for n keys. Returns where the sorted keys are, `keys` or
// `scratch` (each digit pass moves them from one to the other); the other holds garbage.
uint64_t* radixSortByBits(uint64_t* keys, uint64_t* scratch, size_t n, int lowBit, int bitCount);
// The same on vectors: the sorted keys end in `keys`; `scratch` is sized to keys.size()
// (accel/overwrite_buffer.h) and left holding garbage.
void radixSortByBits(std::vector<uint64_t>& keys, std::vector<uint64_t>& scratch, int lowBit, int bitCount);

}  // namespace photon
