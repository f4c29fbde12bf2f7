// Raw Embree closest-hit throughput for random rays in a scene: the ceiling the photon
// pass is measured against.
#pragma once
#include <cstdint>
#include "scene/scene.h"

namespace photon::bench {

struct RayThroughput {
    int64_t rays = 0, hits = 0;
    double seconds = 0;
    double raysPerSecond() const { return seconds > 0 ? static_cast<double>(rays) / seconds : 0; }
    RayThroughput& operator+=(const RayThroughput& o) {
        rays += o.rays;
        hits += o.hits;
        seconds += o.seconds;
        return *this;
    }
};

// Rays start at uniform points in the scene's bounding box with uniform directions,
// incoherent like photon paths; cast with rtcIntersect1 over all TBB threads.
RayThroughput measureEmbreeThroughput(const Scene& scene, int64_t rays);
// The same rays sixteen at a time, with Embree's packet query (Scene::intersect(RayPacket&)),
// as the photon walk casts its lanes' rays.
RayThroughput measureEmbreePacketThroughput(const Scene& scene, int64_t rays);

}  // namespace photon::bench
