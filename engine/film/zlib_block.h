// A header of plain bytes followed by a zlib-compressed array: the binary form of what
// renders hand between processes (pass sums, exact images). The header is the caller's; this
// packs and checks the compressed part.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace photon {

// `header` then `bytes` compressed at zlib level 1 (these buffers go out often, and the
// faster levels compress float and fixed-point pixels nearly as well).
std::string packZlibBlock(std::string_view header, const void* bytes, size_t size);
// Uncompresses what follows `headerSize` bytes of `block` into exactly `size` bytes at
// `out`; false if the block is damaged or holds another amount.
bool unpackZlibBlock(std::string_view block, size_t headerSize, void* out, size_t size);

}  // namespace photon
