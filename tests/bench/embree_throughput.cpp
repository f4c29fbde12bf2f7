#include "embree_throughput.h"
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <chrono>
#include "math/rng.h"
#include "math/sampling.h"

namespace photon::bench {

RayThroughput measureEmbreeThroughput(const Scene& scene, int64_t rays) {
    Vec3 lo = scene.boundsMin(), extent = scene.boundsMax() - lo;
    auto start = std::chrono::steady_clock::now();
    int64_t hits = tbb::parallel_reduce(
        tbb::blocked_range<int64_t>(0, rays, 4096), int64_t(0),
        [&](const tbb::blocked_range<int64_t>& r, int64_t count) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            for (int64_t i = r.begin(); i < r.end(); ++i) {
                Rng rng(1, 0, static_cast<uint64_t>(i), StreamPurpose::Test);
                Vec3 o = lo + extent * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
                Vec3 d = sampleUniformSphere({rng.uniform(), rng.uniform()});
                RTCRayHit rh{};
                rh.ray.org_x = o.x;
                rh.ray.org_y = o.y;
                rh.ray.org_z = o.z;
                rh.ray.dir_x = d.x;
                rh.ray.dir_y = d.y;
                rh.ray.dir_z = d.z;
                rh.ray.tfar = std::numeric_limits<float>::infinity();
                rh.ray.mask = ~0u;
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene.embreeScene(), &context, &rh);
                count += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
            return count;
        },
        std::plus<int64_t>());
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {rays, hits, seconds};
}

}  // namespace photon::bench
