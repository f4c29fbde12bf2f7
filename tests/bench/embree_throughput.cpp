#include "embree_throughput.h"
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <chrono>
#include <limits>
#include "math/rng.h"
#include "math/sampling.h"

namespace photon::bench {

namespace {
// Random ray i: a uniform point of the box, a uniform direction.
Ray randomRay(Vec3 lo, Vec3 extent, int64_t i) {
    Rng rng(1, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
    Vec3 o = lo + extent * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    return {o, sampleUniformSphere({rng.uniform(), rng.uniform()})};
}

// Casts rays [0, count) in blocks over all TBB threads; castBlock(begin, end) returns hits.
template <class CastBlock>
RayThroughput measure(int64_t count, CastBlock castBlock) {
    auto start = std::chrono::steady_clock::now();
    int64_t hits = tbb::parallel_reduce(
        tbb::blocked_range<int64_t>(0, count, 4096), int64_t(0),
        [&](const tbb::blocked_range<int64_t>& r, int64_t sum) { return sum + castBlock(r.begin(), r.end()); },
        std::plus<int64_t>());
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {count, hits, seconds};
}
}  // namespace

RayThroughput measureEmbreeThroughput(const Scene& scene, int64_t rays) {
    const Vec3 lo = scene.boundsMin(), extent = scene.boundsMax() - lo;
    return measure(rays, [&](int64_t begin, int64_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        int64_t hits = 0;
        for (int64_t i = begin; i < end; ++i) {
            RTCRayHit rh = Scene::embreeQuery(randomRay(lo, extent, i));
            rtcIntersect1(scene.embreeScene(), &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
        return hits;
    });
}

RayThroughput measureEmbreePacketThroughput(const Scene& scene, int64_t rays) {
    const Vec3 lo = scene.boundsMin(), extent = scene.boundsMax() - lo;
    return measure(rays, [&](int64_t begin, int64_t end) {
        Scene::RayPacket packet;
        int64_t hits = 0;
        for (int64_t first = begin; first < end; first += Scene::RayPacket::kSize) {
            for (int k = 0; k < Scene::RayPacket::kSize; ++k) {
                if (first + k < end) packet.setLane(k, randomRay(lo, extent, first + k));
                else packet.clearLane(k);
            }
            scene.intersect(packet);
            for (int k = 0; k < Scene::RayPacket::kSize; ++k)
                hits += packet.valid[k] && packet.rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
        }
        return hits;
    });
}

}  // namespace photon::bench
