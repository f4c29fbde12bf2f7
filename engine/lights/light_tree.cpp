#include "lights/light_tree.h"
#include <algorithm>
#include <cmath>
#include <numeric>

namespace photon {
namespace {

constexpr float kPiF = 3.14159265358979f;

float angleOf(float cosTheta) { return std::acos(std::clamp(cosTheta, -1.0f, 1.0f)); }

// v rotated by `angle` about the unit axis k (Rodrigues' formula).
Vec3 rotated(Vec3 v, Vec3 k, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0f - c));
}

}  // namespace

LightBounds unionOf(const LightBounds& a, const LightBounds& b) {
    if (!(a.intensity > 0)) return b;
    if (!(b.intensity > 0)) return a;
    LightBounds u;
    u.lo = vmin(a.lo, b.lo), u.hi = vmax(a.hi, b.hi);
    u.intensity = a.intensity + b.intensity;
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    // The cone: the one of a and b that holds the other, else the smallest cone holding both,
    // its axis turned from a's toward b's.
    const float thetaA = angleOf(a.cosThetaO), thetaB = angleOf(b.cosThetaO);
    const float thetaD = angleOf(dot(a.axis, b.axis));
    if (std::min(thetaD + thetaB, kPiF) <= thetaA) {
        u.axis = a.axis, u.cosThetaO = a.cosThetaO;
    } else if (std::min(thetaD + thetaA, kPiF) <= thetaB) {
        u.axis = b.axis, u.cosThetaO = b.cosThetaO;
    } else {
        const float thetaO = 0.5f * (thetaA + thetaD + thetaB);
        const Vec3 k = cross(a.axis, b.axis);
        if (thetaO >= kPiF || !(length(k) > 1e-7f)) {
            u.axis = a.axis, u.cosThetaO = -1;
        } else {
            u.axis = normalize(rotated(a.axis, normalize(k), thetaO - thetaA));
            // Rounding must not leave either cone's edge outside.
            u.cosThetaO = std::max(-1.0f, std::cos(thetaO) - 1e-4f);
        }
    }
    return u;
}

LightTree::LightTree(const std::vector<LightBounds>& bounds) {
    trail_.assign(bounds.size(), 0);
    depth_.assign(bounds.size(), 0);
    inTree_.assign(bounds.size(), false);
    place_.assign(bounds.size(), 0);
    for (uint32_t i = 0; i < bounds.size(); ++i)
        if (bounds[i].intensity > 0) order_.push_back(i);
    if (order_.empty()) return;
    nodes_.reserve(2 * order_.size() / kClusterSize + 2);
    nodes_.push_back({});
    std::vector<LightBounds> nodeBounds(1);
    build(0, order_, 0, order_.size(), bounds, nodeBounds, 0, 0);
    nodeImportances_ = LightImportances(nodeBounds);
    for (uint32_t k = 0; k < order_.size(); ++k) place_[order_[k]] = k;
    importances_ = LightImportances(bounds, &order_);
}

// Up to three rounds of median splits of the lights' centres along the widest axis of their
// box cut a node's lights into at most eight children: a balanced tree, the same on every
// machine (ties by index).
void LightTree::build(uint32_t node, std::vector<uint32_t>& lights, size_t begin, size_t end,
                      const std::vector<LightBounds>& bounds, std::vector<LightBounds>& nodeBounds, uint64_t trail,
                      int depth) {
    LightBounds all = bounds[lights[begin]];
    for (size_t i = begin + 1; i < end; ++i) all = unionOf(all, bounds[lights[i]]);
    nodeBounds[node] = all;
    if (end - begin <= kClusterSize) {
        nodes_[node] = Node{static_cast<uint32_t>(begin), static_cast<uint32_t>(end - begin), true};
        for (size_t i = begin; i < end; ++i) {
            const uint32_t light = lights[i];
            trail_[light] = trail, depth_[light] = static_cast<uint8_t>(depth), inTree_[light] = true;
        }
        return;
    }
    auto centre = [&](uint32_t i) { return (bounds[i].lo + bounds[i].hi) * 0.5f; };
    std::vector<std::pair<size_t, size_t>> parts{{begin, end}};
    for (int round = 0; round < 3; ++round) {
        std::vector<std::pair<size_t, size_t>> next;
        for (auto [b, e] : parts) {
            if (e - b <= kClusterSize) {
                next.push_back({b, e});
                continue;
            }
            Vec3 lo = centre(lights[b]), hi = lo;
            for (size_t i = b; i < e; ++i) lo = vmin(lo, centre(lights[i])), hi = vmax(hi, centre(lights[i]));
            const Vec3 extent = hi - lo;
            const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
            const size_t middle = b + (e - b) / 2;
            std::nth_element(lights.begin() + b, lights.begin() + middle, lights.begin() + e, [&](uint32_t x, uint32_t y) {
                const float cx = centre(x)[axis], cy = centre(y)[axis];
                return cx < cy || (cx == cy && x < y);
            });
            next.push_back({b, middle});
            next.push_back({middle, e});
        }
        parts = std::move(next);
    }
    const uint32_t first = static_cast<uint32_t>(nodes_.size());
    nodes_[node] = Node{first, static_cast<uint32_t>(parts.size()), false};
    nodes_.resize(nodes_.size() + parts.size());
    nodeBounds.resize(nodes_.size());
    for (uint32_t c = 0; c < parts.size(); ++c)
        build(first + c, lights, parts[c].first, parts[c].second, bounds, nodeBounds,
              trail | (uint64_t(c) << (3 * depth)), depth + 1);
}

// The one with importance whose share of [0, sum) holds u * sum; the last one with
// importance takes what rounding leaves past the end.
LightTree::Choice LightTree::choose(const float* each, uint32_t count, float sum, float u) {
    const float target = u * sum;
    uint32_t last = 0;
    for (uint32_t k = 0; k < count; ++k)
        if (each[k] > 0) last = k;
    float below = 0;
    uint32_t k = 0;
    while (k < last && (!(each[k] > 0) || target >= below + each[k])) below += each[k++];
    return {k, each[k] / sum, std::clamp((target - below) / each[k], 0.0f, 0.99999994f)};
}

LightTree::Pick LightTree::pick(float u, Vec3 p, Vec3 n) const {
    if (nodes_.empty()) return {};
    uint32_t node = 0;
    float probability = 1;
    float each[kClusterSize];
    while (!nodes_[node].leaf) {
        const Node& inner = nodes_[node];
        const float sum = nodeImportances_.evaluate(inner.first, inner.count, p, n, each);
        if (!(sum > 0)) return {};
        const Choice c = choose(each, inner.count, sum, u);
        probability *= c.probability;
        u = c.rest;
        node = inner.first + c.index;
    }
    const Node& leaf = nodes_[node];
    const float sum = importances_.evaluate(leaf.first, leaf.count, p, n, each);
    if (!(sum > 0)) return {};
    const Choice c = choose(each, leaf.count, sum, u);
    return {order_[leaf.first + c.index], probability * c.probability, c.rest};
}

float LightTree::probability(uint32_t light, Vec3 p, Vec3 n) const {
    if (light >= inTree_.size() || !inTree_[light]) return 0;
    uint32_t node = 0;
    float probability = 1;
    float each[kClusterSize];
    for (int d = 0; d < depth_[light]; ++d) {
        const Node& inner = nodes_[node];
        const float sum = nodeImportances_.evaluate(inner.first, inner.count, p, n, each);
        if (!(sum > 0)) return 0;
        const uint32_t c = static_cast<uint32_t>(trail_[light] >> (3 * d) & 7u);
        probability *= each[c] / sum;
        node = inner.first + c;
    }
    const Node& leaf = nodes_[node];
    const float sum = importances_.evaluate(leaf.first, leaf.count, p, n, each);
    return sum > 0 ? probability * (each[place_[light] - leaf.first] / sum) : 0.0f;
}

}  // namespace photon
