// The grid's radix sort against std::stable_sort: keys in the order of the chosen bits,
// ties in their first order, for bit counts that take one, two and three digit passes,
// and the same result with one thread as with many.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <algorithm>
#include <vector>
#include "accel/radix_sort.h"
#include "math/rng.h"

namespace photon {
namespace {

std::vector<uint64_t> randomKeys(size_t n, uint64_t seed) {
    std::vector<uint64_t> keys(n);
    for (size_t i = 0; i < n; ++i) {
        Rng rng(seed, 0, i, StreamPurpose::Test);
        keys[i] = (static_cast<uint64_t>(rng.next()) << 32) | rng.next();
    }
    return keys;
}

void expectSortedLikeStableSort(size_t n, int lowBit, int bitCount) {
    std::vector<uint64_t> keys = randomKeys(n, static_cast<uint64_t>(bitCount)), scratch;
    std::vector<uint64_t> expected = keys;
    const uint64_t mask = bitCount == 64 ? ~uint64_t(0) : ((uint64_t(1) << bitCount) - 1);
    std::stable_sort(expected.begin(), expected.end(),
                     [&](uint64_t a, uint64_t b) { return ((a >> lowBit) & mask) < ((b >> lowBit) & mask); });
    std::vector<uint64_t> single = keys;
    radixSortByBits(keys, scratch, lowBit, bitCount);
    EXPECT_EQ(keys, expected) << bitCount << " bits from bit " << lowBit;
    tbb::task_arena(1).execute([&] { radixSortByBits(single, scratch, lowBit, bitCount); });
    EXPECT_EQ(single, expected);
}

TEST(RadixSort, SortsByTheChosenBitsAndKeepsTiesInOrder) {
    expectSortedLikeStableSort(50000, 32, 8);   // one pass, many ties
    expectSortedLikeStableSort(50000, 32, 18);  // two passes, as the grid's buckets
    expectSortedLikeStableSort(50000, 40, 24);  // three passes
    expectSortedLikeStableSort(7, 32, 18);      // fewer keys than pieces
    expectSortedLikeStableSort(0, 32, 18);
}

}  // namespace
}  // namespace photon
