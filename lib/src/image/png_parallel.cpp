// encode_png_gray(mask, threads): a PNG written by hand around zlib, so the deflating can be
// split across threads (libpng deflates one stream on the calling thread only).
//
// PNG layout (ISO/IEC 15948): the 8-byte signature, then chunks of {length (4 bytes, big
// endian), type (4), data, CRC-32 of type and data}: IHDR (width, height, bit depth 8, colour
// type 0 = gray, compression 0, filter 0, interlace 0), one IDAT holding the zlib stream of the
// scanlines (each row prefixed by its filter byte, 0 = none, as the libpng writer uses), IEND.
//
// The zlib stream (RFC 1950) is a 2-byte header, raw deflate data (RFC 1951) and the Adler-32 of
// the uncompressed bytes. Band k of the rows is deflated raw on its own; every band but the last
// ends with Z_SYNC_FLUSH (a non-final empty stored block, so the next band's blocks start on a
// byte boundary) and the last with Z_FINISH (the final block), so their concatenation is one
// valid deflate stream. The Adler-32s of the bands are joined with adler32_combine.
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "bezel/image.hpp"

namespace bezel {

namespace {

constexpr int kLevel = 1;  // as the libpng writer (encode_png.cpp): speed over size

struct Band {
    int y0 = 0, y1 = 0;
    std::vector<std::uint8_t> deflated;
    uLong adler = 0, length = 0;
    bool ok = false;
};

void deflate_band(ConstMaskView mask, bool last, Band& band) {
    z_stream z{};
    if (deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return;
    const uLong raw = static_cast<uLong>(band.y1 - band.y0) * (static_cast<uLong>(mask.width) + 1);
    band.deflated.resize(deflateBound(&z, raw) + 16);
    z.next_out = band.deflated.data();
    z.avail_out = static_cast<uInt>(band.deflated.size());
    band.adler = adler32(0L, Z_NULL, 0);
    static const Bytef kFilterNone = 0;
    bool ok = true;
    for (int y = band.y0; y < band.y1 && ok; ++y) {
        const bool end = y + 1 == band.y1;
        z.next_in = const_cast<Bytef*>(&kFilterNone);
        z.avail_in = 1;
        ok = deflate(&z, Z_NO_FLUSH) == Z_OK;
        z.next_in = const_cast<Bytef*>(mask.row(y));
        z.avail_in = static_cast<uInt>(mask.width);
        const int flush = !end ? Z_NO_FLUSH : last ? Z_FINISH : Z_SYNC_FLUSH;
        const int rc = deflate(&z, flush);
        ok = ok && (flush == Z_FINISH ? rc == Z_STREAM_END : rc == Z_OK) && z.avail_in == 0;
        band.adler = adler32(band.adler, &kFilterNone, 1);
        band.adler = adler32(band.adler, mask.row(y), static_cast<uInt>(mask.width));
    }
    band.length = raw;
    band.deflated.resize(band.deflated.size() - z.avail_out);
    deflateEnd(&z);
    band.ok = ok;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// Appends a chunk whose data is written by fill(out) right after the type.
template <typename Fill>
void chunk(std::vector<std::uint8_t>& out, const char type[4], Fill&& fill) {
    const std::size_t at = out.size();
    put32(out, 0);  // length, patched below
    out.insert(out.end(), type, type + 4);
    fill(out);
    const std::size_t length = out.size() - at - 8;
    for (int i = 0; i < 4; ++i) out[at + i] = static_cast<std::uint8_t>(length >> (24 - 8 * i));
    put32(out, static_cast<std::uint32_t>(
                   crc32(0L, out.data() + at + 4, static_cast<uInt>(length + 4))));
}

}  // namespace

Expected<std::vector<std::uint8_t>> encode_png_gray(ConstMaskView mask, int threads) {
    const int bands = std::min({threads, kMaxPngThreads, mask.height / kPngRowsPerThread});
    if (bands <= 1 || mask.width <= 0 || mask.width > kMaxImageDim || mask.height > kMaxImageDim ||
        mask.data == nullptr)
        return encode_png_gray(mask);  // which also names any problem with the mask
    std::vector<Band> band(static_cast<std::size_t>(bands));
    for (int k = 0; k < bands; ++k) {
        band[k].y0 = static_cast<int>(static_cast<long long>(mask.height) * k / bands);
        band[k].y1 = static_cast<int>(static_cast<long long>(mask.height) * (k + 1) / bands);
    }
    // Bands 1.. on threads, band 0 here; a thread that cannot be started leaves its band to
    // this thread afterwards.
    std::vector<std::thread> workers;
    std::vector<bool> started(band.size(), false);
    for (int k = 1; k < bands; ++k) {
        try {
            workers.emplace_back(deflate_band, mask, k + 1 == bands, std::ref(band[k]));
            started[k] = true;
        } catch (const std::system_error&) {
        }
    }
    deflate_band(mask, bands == 1, band[0]);
    for (std::thread& t : workers) t.join();
    for (int k = 1; k < bands; ++k)
        if (!started[k]) deflate_band(mask, k + 1 == bands, band[k]);
    uLong adler = band[0].adler;
    std::size_t total = 0;
    for (int k = 0; k < bands; ++k) {
        if (!band[k].ok) return Error{"PNG encoding failed: zlib could not deflate the image"};
        if (k > 0) adler = adler32_combine(adler, band[k].adler, static_cast<z_off_t>(band[k].length));
        total += band[k].deflated.size();
    }

    std::vector<std::uint8_t> out;
    out.reserve(total + 64);
    static const std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    out.insert(out.end(), kSignature, kSignature + 8);
    chunk(out, "IHDR", [&](std::vector<std::uint8_t>& o) {
        put32(o, static_cast<std::uint32_t>(mask.width));
        put32(o, static_cast<std::uint32_t>(mask.height));
        const std::uint8_t rest[5] = {8, 0, 0, 0, 0};  // depth, gray, deflate, filter 0, no interlace
        o.insert(o.end(), rest, rest + 5);
    });
    chunk(out, "IDAT", [&](std::vector<std::uint8_t>& o) {
        o.push_back(0x78);  // deflate, 32 KiB window
        o.push_back(0x01);  // fastest level; (0x78·256 + 0x01) % 31 == 0
        for (const Band& b : band) o.insert(o.end(), b.deflated.begin(), b.deflated.end());
        put32(o, static_cast<std::uint32_t>(adler));
    });
    chunk(out, "IEND", [](std::vector<std::uint8_t>&) {});
    return out;
}

}  // namespace bezel
