// A fixed-size batch of photon hits waiting to be gathered into visible points.
#pragma once
#include <array>
#include "sppm.h"

namespace photon {

class SppmIntegrator::GatherBatch {
public:
    static constexpr size_t kCapacity = 64;
    void push(const PhotonHit& hit) { hits_[size_++] = hit; }
    bool full() const { return size_ == kCapacity; }
    size_t size() const { return size_; }
    const PhotonHit& operator[](size_t i) const { return hits_[i]; }
    void clear() { size_ = 0; }

private:
    std::array<PhotonHit, kCapacity> hits_;
    size_t size_ = 0;
};

}  // namespace photon
