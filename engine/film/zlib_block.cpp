#include "film/zlib_block.h"
#include <zlib.h>
#include <cstring>
#include <stdexcept>

namespace photon {

std::string packZlibBlock(std::string_view header, const void* bytes, size_t size) {
    uLongf packed = compressBound(uLong(size));
    std::string out(header.size() + packed, '\0');
    std::memcpy(out.data(), header.data(), header.size());
    if (compress2(reinterpret_cast<Bytef*>(out.data() + header.size()), &packed, static_cast<const Bytef*>(bytes),
                  uLong(size), 1) != Z_OK)
        throw std::runtime_error("zlib compression failed");
    out.resize(header.size() + packed);
    return out;
}

bool unpackZlibBlock(std::string_view block, size_t headerSize, void* out, size_t size) {
    if (block.size() < headerSize) return false;
    uLongf got = uLongf(size);
    return uncompress(static_cast<Bytef*>(out), &got, reinterpret_cast<const Bytef*>(block.data() + headerSize),
                      uLong(block.size() - headerSize)) == Z_OK &&
           got == size;
}

}  // namespace photon
