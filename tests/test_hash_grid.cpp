// The spatial hash grid SPPM finds visible points with: every sphere that contains a point
// is among the entries of that point's bucket (checked against brute force), spheres
// without a radius are left out, and points outside the grid have no bucket.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <algorithm>
#include <vector>
#include "accel/hash_grid.h"
#include "math/rng.h"

namespace photon {
namespace {

struct Spheres {
    std::vector<Vec3> centers;
    std::vector<float> radii;
};

// Centers in the unit cube; radii from 0.002 to 0.06 (so some spheres span many cells of a
// grid sized by the mean radius), every 50th radius 0.
Spheres randomSpheres(size_t n) {
    Spheres s;
    for (size_t i = 0; i < n; ++i) {
        Rng rng(7, 0, i, StreamPurpose::Test);
        s.centers.push_back({rng.uniform(), rng.uniform(), rng.uniform()});
        float u = rng.uniform();
        s.radii.push_back(i % 50 == 0 ? 0.0f : 0.002f + 0.058f * u * u);
    }
    return s;
}

HashGrid buildGrid(const Spheres& s) {
    std::vector<HashGrid::Sphere> spheres;
    for (size_t i = 0; i < s.centers.size(); ++i) spheres.push_back({s.centers[i], s.radii[i] * s.radii[i]});
    HashGrid grid;
    grid.build(spheres);
    return grid;
}

// The spheres that may hold p: those entered in its bucket on every level, without the
// repeated entries (which hold no point).
std::vector<uint32_t> bucketEntries(const HashGrid& grid, const Spheres& s, Vec3 p) {
    std::vector<uint32_t> entries;
    for (int level = 0; level < grid.levelCount(); ++level) {
        uint32_t bucket = grid.bucketOf(p, level);
        if (bucket == HashGrid::kNoBucket) continue;
        HashGrid::Span span = grid.bucket(bucket);
        for (uint32_t k = 0; k < span.size; ++k) {  // each entry carries its sphere
            const uint32_t i = HashGrid::sphereOf(span.entries[k]);
            if (HashGrid::levelOf(span.entries[k]) != static_cast<uint32_t>(level)) continue;  // another level's cell
            EXPECT_EQ(span.spheres[k].center, s.centers[i]);
            if (span.spheres[k].radiusSquared < 0) continue;
            EXPECT_EQ(span.spheres[k].radiusSquared, s.radii[i] * s.radii[i]);
            entries.push_back(i);
        }
    }
    std::sort(entries.begin(), entries.end());
    // A sphere is on one level, and once in a bucket: a photon is added to it once.
    EXPECT_TRUE(std::adjacent_find(entries.begin(), entries.end()) == entries.end());
    return entries;
}

TEST(HashGrid, EveryContainingSphereIsInThePointsBucket) {
    const Spheres s = randomSpheres(4000);
    const HashGrid grid = buildGrid(s);
    size_t containing = 0;
    for (uint64_t q = 0; q < 20000; ++q) {
        Rng rng(7, 1, q, StreamPurpose::Test);
        // Query points reach a little past the cube, where sphere edges still are.
        Vec3 p{1.1f * rng.uniform() - 0.05f, 1.1f * rng.uniform() - 0.05f, 1.1f * rng.uniform() - 0.05f};
        std::vector<uint32_t> entries = bucketEntries(grid, s, p);
        for (size_t i = 0; i < s.centers.size(); ++i) {
            if (s.radii[i] > 0 && lengthSquared(p - s.centers[i]) <= s.radii[i] * s.radii[i]) {
                ++containing;
                EXPECT_TRUE(std::binary_search(entries.begin(), entries.end(), static_cast<uint32_t>(i)))
                    << "sphere " << i << " contains the point but is not in its bucket";
            }
        }
        for (uint32_t e : entries) ASSERT_GT(s.radii[e], 0) << "a sphere without a radius was entered";
    }
    EXPECT_GT(containing, 2000u);  // the check saw many spheres, not a handful
}

TEST(HashGrid, PointsOnTheSurfaceAreInsideAndPointsFarOutsideHaveNoBucket) {
    Spheres s;
    s.centers = {{0.5f, 0.5f, 0.5f}, {0.2f, 0.3f, 0.9f}};
    s.radii = {0.125f, 0.03125f};  // exact in binary: p - c and r*r are exact too
    const HashGrid grid = buildGrid(s);
    std::vector<uint32_t> atSurface = bucketEntries(grid, s, {0.625f, 0.5f, 0.5f});
    EXPECT_TRUE(std::binary_search(atSurface.begin(), atSurface.end(), 0u));
    for (int level = 0; level < grid.levelCount(); ++level) {
        EXPECT_EQ(grid.bucketOf({5, 5, 5}, level), HashGrid::kNoBucket);
        EXPECT_EQ(grid.bucketOf({-1, 0.5f, 0.5f}, level), HashGrid::kNoBucket);
    }
    EXPECT_GE(grid.entryCount(), 2u);
}

// Radii growing with distance, as on a floor receding to the horizon (the mean radius is
// small against the far ones): no sphere enters more than three cells along an axis, and
// every containing sphere is still found. The near spheres stay in small cells: a point
// among them has few candidates.
TEST(HashGrid, SpreadRadiiKeepTheGridSmall) {
    Spheres s;
    for (size_t i = 0; i < 20000; ++i) {
        Rng rng(7, 3, i, StreamPurpose::Test);
        float depth = 1.0f / (rng.uniform() + 0.001f);  // image rows toward the horizon
        s.centers.push_back({100.0f * (rng.uniform() - 0.5f), 0.0f, -depth});
        s.radii.push_back(0.002f * (1.0f + depth));
    }
    const HashGrid grid = buildGrid(s);
    EXPECT_LE(grid.entryCount(), 9 * s.centers.size());  // a plane: at most 3 x 3 cells each
    EXPECT_GT(grid.levelCount(), 1);
    size_t nearCandidates = 0;
    for (int level = 0; level < grid.levelCount(); ++level) {
        uint32_t bucket = grid.bucketOf(s.centers[0], level);  // depth ~1
        if (bucket != HashGrid::kNoBucket) nearCandidates += grid.bucket(bucket).size;
    }
    EXPECT_LT(nearCandidates, 200u);
    for (uint64_t q = 0; q < 2000; ++q) {
        Rng rng(7, 4, q, StreamPurpose::Test);
        size_t i = q * 7 % s.centers.size();
        // A point inside sphere i, on the plane.
        Vec3 p = s.centers[i] + Vec3(0.7f * s.radii[i] * (2 * rng.uniform() - 1), 0, 0.7f * s.radii[i] * (2 * rng.uniform() - 1));
        std::vector<uint32_t> entries = bucketEntries(grid, s, p);
        ASSERT_TRUE(std::binary_search(entries.begin(), entries.end(), static_cast<uint32_t>(i))) << i;
    }
}

// The grid is built by a stable sort, so each bucket lists its spheres in index order and
// the grid does not depend on the number of threads that built it.
TEST(HashGrid, BucketsListSpheresInIndexOrderWhateverTheThreads) {
    const Spheres s = randomSpheres(20000);
    HashGrid one;
    tbb::task_arena(1).execute([&] { one = buildGrid(s); });
    const HashGrid many = buildGrid(s);
    EXPECT_EQ(one.entryCount(), many.entryCount());
    size_t seen = 0;
    ASSERT_EQ(one.levelCount(), many.levelCount());
    for (uint64_t q = 0; q < 5000; ++q) {
        Rng rng(7, 2, q, StreamPurpose::Test);
        Vec3 p{rng.uniform(), rng.uniform(), rng.uniform()};
        for (int level = 0; level < one.levelCount(); ++level) {
            const uint32_t bucket = one.bucketOf(p, level);
            ASSERT_EQ(bucket, many.bucketOf(p, level));
            if (bucket == HashGrid::kNoBucket) continue;
            const HashGrid::Span a = one.bucket(bucket), b = many.bucket(bucket);
            ASSERT_EQ(a.size, b.size);
            for (uint32_t k = 0; k < a.size; ++k) {
                ASSERT_EQ(a.entries[k], b.entries[k]);
                if (k > 0) ASSERT_LE(HashGrid::sphereOf(a.entries[k - 1]), HashGrid::sphereOf(a.entries[k]));
            }
            seen += a.size;
        }
    }
    EXPECT_GT(seen, 5000u);
}

}  // namespace
}  // namespace photon
