// What one client may ask of the server: keeps a single request from exhausting memory,
// disk or render time.
#pragma once
#include <cstddef>
#include <cstdint>

namespace photon::server {

struct Limits {
    int64_t maxPixels = 4096LL * 4096;       // width * height
    int64_t maxPasses = 100000;
    int64_t maxPhotonsPerPass = 100000000;   // 10^8
    size_t maxBodyBytes = 64u << 20;         // whole request body (HTTP 413 beyond)
    size_t maxAssetBytes = 64u << 20;        // each uploaded asset file (HTTP 422 beyond)
};

}  // namespace photon::server
