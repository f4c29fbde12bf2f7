// A binary tree over many finite lights' bounds, for picking one in proportion to its
// importance at a point in O(log n) (pbrt-v4's BVHLightSampler, 4th ed., sec. 12.6.3; Conty
// Estevez & Kulla 2018): each node holds the union of its lights' bounds, and the walk from
// the root goes to each child in proportion to its bound's importance. A leaf holds a cluster
// of up to kClusterSize lights, among which the walk's last choice is made by each light's
// own bound: the nearest lights, which a node's coarse bound cannot tell apart, are weighed
// one by one. The probability of a light is the product of the choices on its path, which
// probability() retraces with the same arithmetic as pick(), so the two agree to the bit.
#pragma once
#include <cstdint>
#include <vector>
#include "lights/light_bounds.h"

namespace photon {

class LightTree {
public:
    LightTree() = default;
    // `bounds[i]` for light i; lights of zero intensity are left out (never picked).
    explicit LightTree(const std::vector<LightBounds>& bounds);
    bool empty() const { return nodes_.empty(); }

    struct Pick {
        uint32_t light = 0;
        float probability = 0;  // 0: nothing can reach the point
    };
    Pick pick(float u, Vec3 p, Vec3 n) const;
    float probability(uint32_t light, Vec3 p, Vec3 n) const;

    static constexpr uint32_t kClusterSize = 16;

private:
    struct Node {
        LightBounds bounds;          // for the build
        LightImportance importance;  // for the walk
        uint32_t secondChild = 0;  // interior: the first child follows the node
        uint32_t first = 0, count = 0;  // leaf: its lights, order_[first, first + count)
        bool leaf = false;
    };
    // The importances of a leaf's lights at p, into `out`; their sum.
    float clusterImportances(const Node& leaf, Vec3 p, Vec3 n, float* out) const;
    uint32_t build(std::vector<uint32_t>& lights, size_t begin, size_t end, const std::vector<LightBounds>& bounds,
                   uint64_t trail, int depth);

    std::vector<Node> nodes_;
    std::vector<uint32_t> order_;               // the lights, each leaf's together
    std::vector<LightImportance> importances_;  // by place in order_
    std::vector<uint32_t> place_;               // by light: its place in order_
    // By light: the branches from the root to its leaf (bit d set: the second child at depth
    // d; median splits keep the depth near log2(n / kClusterSize), far below 64) and how many
    // there are.
    std::vector<uint64_t> trail_;
    std::vector<uint8_t> depth_;
    std::vector<bool> inTree_;
};

// The union of two lights' bounds: the box around both, their intensities summed, a cone
// holding both cones (pbrt-v4's DirectionCone Union) and the wider falloff.
LightBounds unionOf(const LightBounds& a, const LightBounds& b);

}  // namespace photon
