// gzip-compressed scene files: pbrt-v4 reads any file whose name ends in ".gz" through zlib
// (its Include and Import files, and PLY meshes, e.g. "geometry/ganesha.ply.gz"), and so
// does photon. The decompressed size is bounded by the caller, so that a small file that
// inflates to gigabytes (a "zip bomb") is refused before it is held in memory.
#pragma once
#include <cstddef>
#include <string>
#include <stdexcept>
#include <string_view>

namespace photon {

// Whether `bytes` starts with gzip's magic number (RFC 1952: 1f 8b).
bool isGzip(std::string_view bytes);

// What gunzip throws when the data would decompress to more than it may.
struct GunzipLimitExceeded : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The decompressed contents of a gzip stream (one member or several one after another, as
// `cat a.gz b.gz` makes). Throws std::runtime_error naming `name` when the data are not
// gzip, are damaged or cut short, or (GunzipLimitExceeded) would decompress to more than `maxBytes`.
std::string gunzip(std::string_view compressed, size_t maxBytes, const std::string& name);

}  // namespace photon
