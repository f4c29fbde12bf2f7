#include "photon_map.h"
#include <nanoflann.hpp>
#include "photon_kernel.h"

namespace photon {

namespace {
// Photons farther off the tangent plane than this fraction of the radius are rejected.
constexpr float kDiscThickness = 0.125f;
}  // namespace

// nanoflann reads points through an adaptor; the tree keeps a reference to it.
struct PhotonMap::Tree {
    struct Points {
        const std::vector<StoredPhoton>* photons;
        size_t kdtree_get_point_count() const { return photons->size(); }
        float kdtree_get_pt(size_t i, size_t dim) const { return (*photons)[i].p[dim]; }
        template <class Box>
        bool kdtree_get_bbox(Box&) const { return false; }
    };
    using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Points>, Points, 3, uint32_t>;

    explicit Tree(const std::vector<StoredPhoton>& photons)
        : points{&photons}, index(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
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

Color PhotonMap::radiance(const ShadingPoint& sp, Vec3 wo, unsigned lobes, const PhotonLookup& lookup,
                          bool onlyIndirect) const {
    if (photons_.empty()) return Color(0.0f);
    thread_local std::vector<uint32_t> indices;
    thread_local std::vector<float> distances2;
    indices.resize(static_cast<size_t>(lookup.nearest));
    distances2.resize(static_cast<size_t>(lookup.nearest));
    size_t found = nearest(sp.hit.p, lookup.nearest, lookup.maxRadius, indices.data(), distances2.data());
    if (found == 0) return Color(0.0f);
    float r2 = found == indices.size() ? distances2[found - 1] : lookup.maxRadius * lookup.maxRadius;
    if (!(r2 > 0)) return Color(0.0f);
    const float maxOffset = kDiscThickness * std::sqrt(r2);
    const Vec3 woLocal = sp.frame.toLocal(wo);
    Color sum(0.0f);
    for (size_t i = 0; i < found; ++i) {
        const StoredPhoton& ph = photons_[indices[i]];
        if (onlyIndirect && !(ph.flags & StoredPhoton::kIndirect)) continue;
        if (std::abs(dot(ph.position() - sp.hit.p, sp.hit.ng)) > maxOffset) continue;
        Color f = sp.material->eval(woLocal, sp.frame.toLocal(ph.incoming()), sp.tint, TransportMode::Radiance, lobes);
        if (isBlack(f)) continue;
        sum += f * ph.power() * kernelWeight(lookup.kernel, distances2[i] / r2);
    }
    return sum * (fluxScale_ / (kPi * r2));
}

}  // namespace photon
