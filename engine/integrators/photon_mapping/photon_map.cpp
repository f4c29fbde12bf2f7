#include "integrators/photon_mapping/photon_map.h"
#include <tbb/parallel_for.h>
#include <nanoflann.hpp>
#include "integrators/common/photon_kernel.h"

namespace photon {

namespace {
// Photons farther off the tangent plane than this fraction of the radius are rejected.
constexpr float kDiscThickness = 0.125f;
}  // namespace

// nanoflann reads points through an adaptor; the tree keeps a reference to it. It points
// at the photons' storage, which a move of the map's vector leaves in place.
struct PhotonMap::Tree {
    struct Points {
        const StoredPhoton* photons;
        size_t count;
        size_t kdtree_get_point_count() const { return count; }
        float kdtree_get_pt(size_t i, size_t dim) const { return photons[i].p[dim]; }
        template <class Box>
        bool kdtree_get_bbox(Box&) const { return false; }
    };
    using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Points>, Points, 3, uint32_t>;

    explicit Tree(const std::vector<StoredPhoton>& photons)
        : points{photons.data(), photons.size()}, index(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
    Points points;
    Index index;
};

PhotonMap::PhotonMap() = default;
PhotonMap::~PhotonMap() = default;
PhotonMap::PhotonMap(PhotonMap&&) noexcept = default;
PhotonMap& PhotonMap::operator=(PhotonMap&&) noexcept = default;

void PhotonMap::build(std::vector<StoredPhoton> photons, float fluxScale) {
    tree_.reset();
    photons_ = std::move(photons);
    fluxScale_ = fluxScale;
    tree_ = std::make_unique<Tree>(photons_);
}

Color PhotonMap::totalPower() const {
    double sum[3] = {0, 0, 0};
    for (const StoredPhoton& p : photons_) {
        Color c = p.power();
        for (int k = 0; k < 3; ++k) sum[k] += c[k];
    }
    return Color(static_cast<float>(sum[0]), static_cast<float>(sum[1]), static_cast<float>(sum[2])) * fluxScale_;
}

size_t PhotonMap::nearest(Vec3 x, int k, float maxRadius, uint32_t* indices, float* distances2) const {
    if (!tree_ || photons_.empty() || k <= 0) return 0;
    nanoflann::KNNResultSet<float, uint32_t> result(static_cast<size_t>(k));
    result.init(indices, distances2);
    // The result set only accepts points closer than its worst distance, which is the
    // last slot until it is full: starting that slot at maxRadius^2 bounds the search.
    distances2[k - 1] = maxRadius * maxRadius;
    const float q[3] = {x.x, x.y, x.z};
    tree_->index.findNeighbors(result, q, nanoflann::SearchParams());
    return result.size();
}

template <class Weight>
Color PhotonMap::estimate(Vec3 x, Vec3 n, const PhotonLookup& lookup, const Weight& weight) const {
    if (photons_.empty()) return Color(0.0f);
    thread_local std::vector<uint32_t> indices;
    thread_local std::vector<float> distances2;
    indices.resize(static_cast<size_t>(lookup.nearest));
    distances2.resize(static_cast<size_t>(lookup.nearest));
    size_t found = nearest(x, lookup.nearest, lookup.maxRadius, indices.data(), distances2.data());
    if (found == 0) return Color(0.0f);
    float r2 = found == indices.size() ? distances2[found - 1] : lookup.maxRadius * lookup.maxRadius;
    if (!(r2 > 0)) return Color(0.0f);
    const float maxOffset = kDiscThickness * std::sqrt(r2);
    Color sum(0.0f);
    for (size_t i = 0; i < found; ++i) {
        const StoredPhoton& ph = photons_[indices[i]];
        if (std::abs(dot(ph.position() - x, n)) > maxOffset) continue;
        Color w = weight(ph);
        if (isBlack(w)) continue;
        sum += w * ph.power() * kernelWeight(lookup.kernel, distances2[i] / r2);
    }
    return sum * (fluxScale_ / (kPi * r2));
}

Color PhotonMap::radiance(const ShadingPoint& sp, Vec3 wo, unsigned lobes, const PhotonLookup& lookup,
                          bool onlyIndirect) const {
    const Vec3 woLocal = sp.frame.toLocal(wo);
    return estimate(sp.hit.p, sp.hit.ng, lookup, [&](const StoredPhoton& ph) {
        if (onlyIndirect && !(ph.flags & StoredPhoton::kIndirect)) return Color(0.0f);
        return sp.material->eval(woLocal, sp.frame.toLocal(ph.incoming()), sp.inputs, TransportMode::Radiance, lobes);
    });
}

Color PhotonMap::irradiance(Vec3 x, Vec3 n, const PhotonLookup& lookup) const {
    return estimate(x, n, lookup, [&](const StoredPhoton& ph) { return Color(dot(ph.incoming(), n) > 0 ? 1.0f : 0.0f); });
}

PhotonMap PhotonMap::precomputeIrradiance(const std::vector<uint16_t>& normals, int stride,
                                          const PhotonLookup& lookup) const {
    const size_t count = (photons_.size() + stride - 1) / stride;
    std::vector<StoredPhoton> records(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        const StoredPhoton& ph = photons_[i * stride];
        StoredPhoton r = ph;
        r.direction = normals[i * stride];
        Vec3 n = r.incoming();
        r.flux = StoredPhoton::encodeFlux(irradiance(ph.position(), n, lookup));
        records[i] = r;
    });
    PhotonMap map;
    map.build(std::move(records), 1.0f);
    return map;
}

std::optional<Color> PhotonMap::lookupIrradiance(Vec3 x, Vec3 n, float maxRadius) const {
    constexpr int k = 8;
    uint32_t indices[k];
    float distances2[k];
    size_t found = nearest(x, k, maxRadius, indices, distances2);
    for (size_t i = 0; i < found; ++i) {
        const StoredPhoton& r = photons_[indices[i]];
        if (dot(r.incoming(), n) > 0.9f) return r.power();
    }
    return std::nullopt;
}

}  // namespace photon
