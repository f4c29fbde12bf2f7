// Sizing the grid's per-pass buffers, whose old contents are never read again.
#pragma once
#include <cstddef>
#include <vector>

namespace photon {

// Resizes v to n elements that the caller will overwrite. When v must grow, its old buffer
// is released first (a plain resize would copy the old elements into the new buffer, and
// peak memory would hold both) and a quarter more is reserved, since the number of grid
// entries moves a little from pass to pass.
template <class T>
void resizeForOverwrite(std::vector<T>& v, size_t n) {
    if (n > v.capacity()) {
        std::vector<T>().swap(v);
        v.reserve(n + n / 4);
    }
    v.resize(n);
}

}  // namespace photon
