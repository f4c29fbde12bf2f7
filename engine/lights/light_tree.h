// A tree over many finite lights' bounds, for picking one in proportion to its importance at
// a point in O(log n) (pbrt-v4's BVHLightSampler, 4th ed., sec. 12.6.3; Conty Estevez & Kulla
// 2018): each node holds the union of its lights' bounds, and the walk from the root goes to
// each child in proportion to its bound's importance. A node has up to eight children, whose
// bounds are asked at once in SIMD lanes (LightImportances): on a mesh light of 288 triangles
// the binary tree's walk, one bound at a time, was 37% of a path tracer's profile. A leaf
// holds a cluster of up to kClusterSize lights, among which the walk's last choice is made by
// each light's own bound: the nearest lights, which a node's coarse bound cannot tell apart,
// are weighed one by one. The probability of a light is the product of the choices on its
// path, which probability() retraces with the same arithmetic as pick(), so the two agree to
// the bit.
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
        float rest = 0;         // what is left of u within the light's share, rescaled to [0, 1)
    };
    Pick pick(float u, Vec3 p, Vec3 n) const;
    float probability(uint32_t light, Vec3 p, Vec3 n) const;

    static constexpr uint32_t kClusterSize = 16;
    static constexpr uint32_t kMaxChildren = 8;  // three median splits of a node's lights

private:
    struct Node {
        uint32_t first = 0, count = 0;  // interior: its children, nodes [first, first + count);
                                        // leaf: its lights, order_[first, first + count)
        bool leaf = false;
    };
    // The importances at p of nodes (or, for a leaf, lights) [first, first + count): into
    // `out`, their sum. The choice among them, by u, and what is left of u.
    struct Choice {
        uint32_t index = 0;
        float probability = 0;
        float rest = 0;
    };
    static Choice choose(const float* each, uint32_t count, float sum, float u);
    void build(uint32_t node, std::vector<uint32_t>& lights, size_t begin, size_t end,
               const std::vector<LightBounds>& bounds, std::vector<LightBounds>& nodeBounds, uint64_t trail, int depth);

    std::vector<Node> nodes_;                   // the root first; each node's children together
    LightImportances nodeImportances_;          // by node
    std::vector<uint32_t> order_;               // the lights, each leaf's together
    LightImportances importances_;              // by place in order_
    std::vector<uint32_t> place_;               // by light: its place in order_
    // By light: the child taken at each level from the root to its leaf (three bits a level:
    // depth d in bits 3d..3d+2; median splits keep the depth near log8(n / kClusterSize),
    // far below the 21 levels 64 bits hold) and how many levels there are.
    std::vector<uint64_t> trail_;
    std::vector<uint8_t> depth_;
    std::vector<bool> inTree_;
};

// The union of two lights' bounds: the box around both, their intensities summed, a cone
// holding both cones (pbrt-v4's DirectionCone Union) and the wider falloff.
LightBounds unionOf(const LightBounds& a, const LightBounds& b);

}  // namespace photon
