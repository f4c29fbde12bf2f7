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
        RTCRayHit16& p = packet.rh;
        int64_t hits = 0;
        for (int64_t first = begin; first < end; first += Scene::RayPacket::kSize) {
            for (int k = 0; k < Scene::RayPacket::kSize; ++k) {
                const int64_t i = first + k;
                packet.valid[k] = i < end ? -1 : 0;
                const Ray ray = randomRay(lo, extent, i);
                p.ray.org_x[k] = ray.o.x, p.ray.org_y[k] = ray.o.y, p.ray.org_z[k] = ray.o.z;
                p.ray.dir_x[k] = ray.d.x, p.ray.dir_y[k] = ray.d.y, p.ray.dir_z[k] = ray.d.z;
                p.ray.tnear[k] = 0;
                p.ray.tfar[k] = std::numeric_limits<float>::infinity();
                p.ray.time[k] = 0;
                p.ray.mask[k] = ~0u;
                p.ray.flags[k] = 0;
                p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            }
            scene.intersect(packet);
            for (int k = 0; k < Scene::RayPacket::kSize; ++k)
                hits += packet.valid[k] && p.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
        }
        return hits;
    });
}

}  // namespace photon::bench
