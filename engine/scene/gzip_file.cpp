#include "scene/gzip_file.h"
#include <algorithm>
#include <zlib.h>

namespace photon {

bool isGzip(std::string_view bytes) {
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gunzip(std::string_view compressed, size_t maxBytes, const std::string& name) {
    if (!isGzip(compressed)) throw std::runtime_error(name + ": not a gzip file");
    z_stream zs{};
    // 16 + MAX_WBITS: a gzip header and trailer (with its CRC-32 checked), not zlib's.
    if (inflateInit2(&zs, 16 + MAX_WBITS) != Z_OK) throw std::runtime_error(name + ": cannot start zlib");
    struct End {
        z_stream& zs;
        ~End() { inflateEnd(&zs); }
    } end{zs};
    std::string out;
    const auto* next = reinterpret_cast<const Bytef*>(compressed.data());
    size_t left = compressed.size();
    constexpr size_t kChunk = size_t(1) << 20;
    for (;;) {
        // zlib counts in uInt: feed the input in pieces below 4 GiB.
        const uInt in = static_cast<uInt>(std::min<size_t>(left, size_t(1) << 30));
        zs.next_in = const_cast<Bytef*>(next);
        zs.avail_in = in;
        int status = Z_OK;
        while (status == Z_OK && (zs.avail_in > 0 || zs.avail_out == 0)) {
            const size_t before = out.size();
            if (before >= maxBytes)
                throw GunzipLimitExceeded(name + ": decompresses to more than " + std::to_string(maxBytes) + " bytes");
            const size_t room = std::min(kChunk, maxBytes - before);
            out.resize(before + room);
            zs.next_out = reinterpret_cast<Bytef*>(out.data() + before);
            zs.avail_out = static_cast<uInt>(room);
            status = inflate(&zs, Z_NO_FLUSH);
            out.resize(before + (room - zs.avail_out));
            if (status == Z_BUF_ERROR && zs.avail_in == 0) break;  // this piece of input is spent
        }
        const size_t used = in - zs.avail_in;
        next += used;
        left -= used;
        if (status == Z_STREAM_END) {
            // Another member may follow (gzip files can be concatenated).
            if (left == 0) break;
            if (!isGzip({reinterpret_cast<const char*>(next), left}))
                throw std::runtime_error(name + ": data after the end of the gzip stream");
            if (inflateReset(&zs) != Z_OK) throw std::runtime_error(name + ": cannot restart zlib");
            continue;
        }
        if (status != Z_OK && status != Z_BUF_ERROR)
            throw std::runtime_error(name + ": damaged gzip data (" + (zs.msg ? zs.msg : "zlib error") + ")");
        if (left == 0) throw std::runtime_error(name + ": the gzip file is cut short");
    }
    out.shrink_to_fit();
    return out;
}

}  // namespace photon
