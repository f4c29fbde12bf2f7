// A photon map (Jensen 1996): stored photons in a balanced kd-tree (nanoflann) with
// k-nearest-neighbour queries, and the radiance estimate over them.
#pragma once
#include <memory>
#include <optional>
#include <vector>
#include "integrators/common/photon_record.h"
#include "integrators/common/shading.h"

namespace photon {

// How a radiance estimate looks photons up.
struct PhotonLookup {
    int nearest = 50;        // k
    float maxRadius = 1;     // photons farther than this are not used
    KernelKind kernel = KernelKind::Uniform;
};

class PhotonMap {
public:
    PhotonMap();
    ~PhotonMap();
    PhotonMap(PhotonMap&&) noexcept;
    PhotonMap& operator=(PhotonMap&&) noexcept;

    // Takes the photons and builds the tree. fluxScale turns stored flux into watts
    // (the lights' mean power over the number of photons emitted).
    void build(std::vector<StoredPhoton> photons, float fluxScale);
    size_t size() const { return photons_.size(); }
    const StoredPhoton& operator[](size_t i) const { return photons_[i]; }
    // The power all the map's photons carry (W): the light arriving where they were stored.
    Color totalPower() const;

    // The k photons nearest x within maxRadius, nearest first: indices and squared
    // distances written to the arrays (room for k); returns how many were found.
    size_t nearest(Vec3 x, int k, float maxRadius, uint32_t* indices, float* distances2) const;

    // Radiance reflected toward wo through the material's `lobes` (Jensen 2001, eq. 7.6):
    // L = sum_p f(x, wp, wo) Phi_p K(d_p^2 / r^2) / (pi r^2), r the distance to the k-th
    // photon (or the maximum radius if fewer are found). The search sphere is flattened
    // to a disc: photons farther than a fraction of r off the tangent plane are left out
    // (Jensen 2001, sec. 7.2), so corners and thin walls do not leak. With onlyIndirect,
    // photons without StoredPhoton::kIndirect are left out too.
    Color radiance(const ShadingPoint& sp, Vec3 wo, unsigned lobes, const PhotonLookup& lookup,
                   bool onlyIndirect = false) const;

    // Irradiance at x on a surface with normal n (W/m^2): the same estimate with f = 1 for
    // photons arriving from n's side (Christensen 1999, "Faster Photon Map Global
    // Illumination", JGT 4(1)).
    Color irradiance(Vec3 x, Vec3 n, const PhotonLookup& lookup) const;

    // Precomputed irradiance (Christensen 1999): every `stride`-th photon becomes a record
    // at its position whose flux word holds the irradiance there and whose direction word
    // holds the surface normal (normals[i], StoredPhoton::encodeDirection). Parallel and
    // deterministic.
    PhotonMap precomputeIrradiance(const std::vector<uint16_t>& normals, int stride, const PhotonLookup& lookup) const;
    // The irradiance of the nearest record within maxRadius whose normal is within ~25
    // degrees of n, if any (this map must come from precomputeIrradiance).
    std::optional<Color> lookupIrradiance(Vec3 x, Vec3 n, float maxRadius) const;

private:
    // sum_p weight(p) Phi_p K / (pi r^2) over the k nearest photons in the disc about x
    // flattened along n: the one density estimate behind radiance and irradiance.
    template <class Weight>
    Color estimate(Vec3 x, Vec3 n, const PhotonLookup& lookup, const Weight& weight) const;
    struct Tree;
    std::vector<StoredPhoton> photons_;
    std::unique_ptr<Tree> tree_;
    float fluxScale_ = 0;
};

}  // namespace photon
