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

// Child c's share of its parent's choice: the one expression pick() and probability() use.
float share(float importance, float other) { return importance / (importance + other); }

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
    build(order_, 0, order_.size(), bounds, 0, 0);
    for (uint32_t k = 0; k < order_.size(); ++k) {
        place_[order_[k]] = k;
        importances_.emplace_back(bounds[order_[k]]);
    }
}

// Median splits of the lights' centres along the widest axis of their box: a balanced tree
// whose depth stays within the 64 branches a trail holds.
uint32_t LightTree::build(std::vector<uint32_t>& lights, size_t begin, size_t end,
                          const std::vector<LightBounds>& bounds, uint64_t trail, int depth) {
    const uint32_t index = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({});
    if (end - begin <= kClusterSize) {
        LightBounds all = bounds[lights[begin]];
        for (size_t i = begin + 1; i < end; ++i) all = unionOf(all, bounds[lights[i]]);
        nodes_[index] = Node{all, LightImportance(all), 0, static_cast<uint32_t>(begin),
                             static_cast<uint32_t>(end - begin), true};
        for (size_t i = begin; i < end; ++i) {
            const uint32_t light = lights[i];
            trail_[light] = trail, depth_[light] = static_cast<uint8_t>(depth), inTree_[light] = true;
        }
        return index;
    }
    auto centre = [&](uint32_t i) { return (bounds[i].lo + bounds[i].hi) * 0.5f; };
    Vec3 lo = centre(lights[begin]), hi = lo;
    for (size_t i = begin; i < end; ++i) lo = vmin(lo, centre(lights[i])), hi = vmax(hi, centre(lights[i]));
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const size_t middle = begin + (end - begin) / 2;
    std::nth_element(lights.begin() + begin, lights.begin() + middle, lights.begin() + end, [&](uint32_t a, uint32_t b) {
        const float ca = centre(a)[axis], cb = centre(b)[axis];
        return ca < cb || (ca == cb && a < b);  // ties by index: the same tree on every machine
    });
    build(lights, begin, middle, bounds, trail, depth + 1);
    const uint32_t second = build(lights, middle, end, bounds, trail | (uint64_t(1) << depth), depth + 1);
    nodes_[index].secondChild = second;
    nodes_[index].bounds = unionOf(nodes_[index + 1].bounds, nodes_[second].bounds);
    nodes_[index].importance = LightImportance(nodes_[index].bounds);
    return index;
}

float LightTree::clusterImportances(const Node& leaf, Vec3 p, Vec3 n, float* out) const {
    float sum = 0;
    for (uint32_t k = 0; k < leaf.count; ++k) sum += out[k] = importances_[leaf.first + k](p, n);
    return sum;
}

LightTree::Pick LightTree::pick(float u, Vec3 p, Vec3 n) const {
    if (nodes_.empty()) return {};
    uint32_t node = 0;
    float probability = 1;
    while (!nodes_[node].leaf) {
        const uint32_t first = node + 1, second = nodes_[node].secondChild;
        const float i1 = nodes_[first].importance(p, n), i2 = nodes_[second].importance(p, n);
        if (!(i1 > 0) && !(i2 > 0)) return {};
        const float p1 = share(i1, i2);
        if (u < p1) {
            u = std::min(u / p1, 0.99999994f);
            probability *= p1;
            node = first;
        } else {
            const float p2 = share(i2, i1);
            u = std::min((u - p1) / p2, 0.99999994f);
            probability *= p2;
            node = second;
        }
    }
    const Node& leaf = nodes_[node];
    float each[kClusterSize];
    const float sum = clusterImportances(leaf, p, n, each);
    if (!(sum > 0)) return {};
    const float target = u * sum;
    float below = 0;
    uint32_t last = 0;
    for (uint32_t k = 0; k < leaf.count; ++k)
        if (each[k] > 0) last = k;
    uint32_t k = 0;
    while (k < last && (!(each[k] > 0) || target >= below + each[k])) below += each[k++];
    return {order_[leaf.first + k], probability * (each[k] / sum)};
}

float LightTree::probability(uint32_t light, Vec3 p, Vec3 n) const {
    if (light >= inTree_.size() || !inTree_[light]) return 0;
    uint32_t node = 0;
    float probability = 1;
    for (int d = 0; d < depth_[light]; ++d) {
        const uint32_t first = node + 1, second = nodes_[node].secondChild;
        const float i1 = nodes_[first].importance(p, n), i2 = nodes_[second].importance(p, n);
        if (!(i1 > 0) && !(i2 > 0)) return 0;
        if (trail_[light] >> d & 1) {
            probability *= share(i2, i1);
            node = second;
        } else {
            probability *= share(i1, i2);
            node = first;
        }
    }
    const Node& leaf = nodes_[node];
    float each[kClusterSize];
    const float sum = clusterImportances(leaf, p, n, each);
    return sum > 0 ? probability * (each[place_[light] - leaf.first] / sum) : 0.0f;
}

}  // namespace photon
