// encode_png_gray(mask, threads) and PngGrayStream: a PNG written by hand, so the deflating can
// be split across threads (one zlib or igzip stream is one thread's work), can start on
// the top of a page while its bottom is still being drawn, and can use a faster deflater than
// zlib: ISA-L's igzip (Debian libisal-dev).
//
// PNG layout (ISO/IEC 15948): the 8-byte signature, then chunks of {length (4 bytes, big
// endian), type (4), data, CRC-32 of type and data}: IHDR (width, height, bit depth 8, colour
// type 0 = gray, compression 0, filter 0, interlace 0), one IDAT holding the zlib stream of the
// scanlines (each row prefixed by its filter byte, 0 = none, as the libpng writer uses), IEND.
//
// The zlib stream (RFC 1950) is a 2-byte header, raw deflate data (RFC 1951) and the Adler-32 of
// the uncompressed bytes. Band k (rows [64k, 64k + 64)) is deflated raw on its own; every band
// but the last ends with a sync flush (a non-final empty stored block, so the next band's blocks
// start on a byte boundary) and the last with the final block, so their concatenation is one
// valid deflate stream. The Adler-32s of the bands are joined with zlib's adler32_combine.
// PngCompression::Default primes each band's deflater with the 32 KiB of scanlines before it
// (igzip's preset dictionary): a back-reference into them is valid in the joined stream, whose
// window holds exactly those bytes, and the rows above a band are final when it is queued.
//
// Why igzip: on the 716×2361 benchmark page in 64-row bands (one thread), igzip level 1 takes
// 3.7 ms for 292 795 bytes, where zlib level 1 (libpng's fastest) takes about 11 ms for 299 587
// bytes (22 M against 61 M instructions).
// igzip level 0 is faster still (2.5 ms) but 16 % larger. Level 2 primed with the rows above
// (Default) gives 252 943 bytes for ~25 % more time; level 3 is 5x slower for 2 % less.
//
// Why 64-row bands whatever the thread count: a worker can start while a page of text is still
// drawn (a 16 px line of text is ~19 rows), and the bytes do not depend on the core count. The
// price is size when each band starts with an empty history (Fast: +14 % against one igzip
// stream), which priming with the rows above (Default) wins back.
#include <isa-l/igzip_lib.h>
#include <zlib.h>

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "bezel/image.hpp"
#include "image/png_igzip.hpp"

namespace bezel {

// Named (not anonymous): PngGrayStream::Impl, which has external linkage, holds these.
namespace png_detail {

// igzip's levels are 0..3; see above.
int igzip_level(PngCompression c) { return c == PngCompression::Fast ? 1 : 2; }
std::size_t igzip_level_buf_bytes(PngCompression c) {
    // The "small" work buffers (16 Ki tokens), since a band is only ~64 rows (same bytes, same
    // speed as the default sizes).
    return c == PngCompression::Fast ? ISAL_DEF_LVL1_SMALL : ISAL_DEF_LVL2_SMALL;
}
// Default's priming: a deflate window (32 KiB) of the scanlines above the band.
constexpr std::size_t kHistoryBytes = 32768;

// A byte buffer that is not cleared: the deflaters write every byte they later read, and
// clearing fresh memory only faults its pages in early (a page's bands hold ~1.7 MB for 0.3 MB
// of output on a text page).
struct Bytes {
    std::unique_ptr<std::uint8_t[]> data;
    std::size_t size = 0, capacity = 0;
    void reserve_discarding(std::size_t n) {
        if (n > capacity) {
            data.reset(new std::uint8_t[n]);
            capacity = n;
        }
        size = n;
    }
    // Keeps the first `keep` bytes, grows to n.
    void grow(std::size_t keep, std::size_t n) {
        std::unique_ptr<std::uint8_t[]> bigger(new std::uint8_t[n]);
        std::memcpy(bigger.get(), data.get(), keep);
        data = std::move(bigger);
        capacity = size = n;
    }
};

struct Band {
    int y0 = 0, y1 = 0;
    Bytes deflated;
    uLong adler = 0, length = 0;
    bool ok = false;
};

// One igzip work buffer (hash table and 16 Ki tokens, ~84 KiB at level 1) and one scanline
// buffer, reused from band to band.
class Deflater {
public:
    explicit Deflater(PngCompression c)
        : level_(igzip_level(c)), prime_(c == PngCompression::Default) {
        level_buf_.reserve_discarding(igzip_level_buf_bytes(c));
    }

    void run(ConstMaskView mask, bool last, Band& band) {
        // The scanlines as the stream holds them (filter byte 0, then the pixels), from the
        // first row of the history (Default) to the band's end.
        const std::size_t row_bytes = static_cast<std::size_t>(mask.width) + 1;
        const std::size_t history_rows_wanted = (kHistoryBytes + row_bytes - 1) / row_bytes;
        const int history_rows =
            prime_ ? static_cast<int>(
                         std::min(static_cast<std::size_t>(band.y0), history_rows_wanted))
                   : 0;
        const int from = band.y0 - history_rows;
        raw_.reserve_discarding(static_cast<std::size_t>(band.y1 - from) * row_bytes);
        for (int y = from; y < band.y1; ++y) {
            std::uint8_t* r = raw_.data.get() + static_cast<std::size_t>(y - from) * row_bytes;
            r[0] = 0;
            std::memcpy(r + 1, mask.row(y), static_cast<std::size_t>(mask.width));
        }
        const std::size_t history = static_cast<std::size_t>(history_rows) * row_bytes;
        deflate(raw_.data.get() + history, raw_.size - history, history, last, band);
    }

    // Deflates in[0, in_bytes) into band (length, Adler-32, deflated bytes; ok on success),
    // primed with the `history` bytes before `in` (at most a window's worth are used). Every
    // block but the last ends on a byte boundary (a sync flush); with `last`, the final block
    // closes the deflate stream.
    void deflate(const std::uint8_t* in, std::size_t in_bytes, std::size_t history, bool last,
                 Band& band) {
        band.length = in_bytes;
        band.adler = isal_adler32(1, in, in_bytes);
        // Room for stored blocks (5 bytes per 64 KiB) should nothing compress; grown if not.
        band.deflated.reserve_discarding(in_bytes + in_bytes / 64 + 64);
        isal_zstream z;
        isal_deflate_init(&z);
        z.level = static_cast<std::uint32_t>(level_);
        z.level_buf = level_buf_.data.get();
        z.level_buf_size = static_cast<std::uint32_t>(level_buf_.size);
        if (history > 0) {
            const std::size_t dict = std::min(history, kHistoryBytes);
            if (isal_deflate_set_dict(&z, const_cast<std::uint8_t*>(in - dict),
                                      static_cast<std::uint32_t>(dict)) != COMP_OK)
                return;
        }
        z.flush = SYNC_FLUSH;
        z.end_of_stream = last ? 1 : 0;
        z.next_in = const_cast<std::uint8_t*>(in);
        z.avail_in = static_cast<std::uint32_t>(in_bytes);
        z.next_out = band.deflated.data.get();
        z.avail_out = static_cast<std::uint32_t>(band.deflated.size);
        for (;;) {
            if (isal_deflate(&z) != COMP_OK) return;
            // Everything is in (and, for the last band, the final block written) once igzip
            // returns with output room to spare.
            if (z.avail_in == 0 && z.avail_out > 0 &&
                (!last || z.internal_state.state == ZSTATE_END))
                break;
            const std::size_t used = band.deflated.size - z.avail_out;
            band.deflated.grow(used, band.deflated.size * 2);
            z.next_out = band.deflated.data.get() + used;
            z.avail_out = static_cast<std::uint32_t>(band.deflated.size - used);
        }
        band.deflated.size -= z.avail_out;
        band.ok = true;
    }

private:
    int level_;
    bool prime_;
    Bytes level_buf_, raw_;
};

}  // namespace png_detail

using png_detail::Band;
using png_detail::Deflater;

namespace {

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

// The PNG file around one zlib stream made of the deflate pieces bands[0, n) in order (the
// last one holding the final block) and the Adler-32 of all their input: the signature, IHDR
// (8 bits a sample, `color_type`, no interlace), one IDAT, IEND.
std::vector<std::uint8_t> png_file(int width, int height, std::uint8_t color_type,
                                   PngCompression compression, const Band* bands, int n,
                                   uLong adler) {
    std::size_t total = 0;
    for (int k = 0; k < n; ++k) total += bands[k].deflated.size;
    std::vector<std::uint8_t> out;
    out.reserve(total + 64);
    static const std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    out.insert(out.end(), kSignature, kSignature + 8);
    chunk(out, "IHDR", [&](std::vector<std::uint8_t>& o) {
        put32(o, static_cast<std::uint32_t>(width));
        put32(o, static_cast<std::uint32_t>(height));
        // depth, colour type, deflate, filter method 0, no interlace
        const std::uint8_t rest[5] = {8, color_type, 0, 0, 0};
        o.insert(o.end(), rest, rest + 5);
    });
    chunk(out, "IDAT", [&](std::vector<std::uint8_t>& o) {
        o.push_back(0x78);  // deflate, 32 KiB window
        // FLEVEL (informative): fastest (0x01) or fast (0x5E); (0x78·256 + FLG) % 31 == 0.
        o.push_back(compression == PngCompression::Fast ? 0x01 : 0x5E);
        for (int k = 0; k < n; ++k)
            o.insert(o.end(), bands[k].deflated.data.get(),
                     bands[k].deflated.data.get() + bands[k].deflated.size);
        put32(o, static_cast<std::uint32_t>(adler));
    });
    chunk(out, "IEND", [](std::vector<std::uint8_t>&) {});
    return out;
}

}  // namespace

// The bands' shared state: bands [0, queued) may be taken, [0, taken) have been.
struct PngGrayStream::Impl {
    ConstMaskView page;
    PngOptions options;
    bool banded = false;  // false: finish() is the one-thread writer (encode_png_gray)
    bool finished = false;
    int next_band_end = 0;  // rows_final's fast path: the row count that completes band `queued`
    std::vector<Band> bands;
    std::mutex mutex;
    std::condition_variable wake;
    int queued = 0, taken = 0;
    bool stop = false;
    std::vector<std::thread> workers;

    // Deflates queued bands until none is left untaken; with `wait`, then sleeps for more
    // until stopped (a worker), else returns (the finishing thread).
    void work(bool wait) {
        Deflater deflater(options.compression);
        std::unique_lock<std::mutex> lock(mutex);
        for (;;) {
            if (wait) wake.wait(lock, [&] { return stop || taken < queued; });
            if (taken >= queued) return;
            const int k = taken++;
            lock.unlock();
            deflater.run(page, k + 1 == static_cast<int>(bands.size()), bands[k]);
            lock.lock();
        }
    }

    Expected<std::vector<std::uint8_t>> assemble();
};

PngGrayStream::PngGrayStream(ConstMaskView page, int workers, const PngOptions& options)
    : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.page = page;
    s.options = options;
    s.banded = options.compression != PngCompression::Small && page.data != nullptr &&
               page.width > 0 && page.width <= kMaxImageDim &&
               page.height >= 2 * kPngBandRows && page.height <= kMaxImageDim;
    if (!s.banded) return;
    const int n = (page.height + kPngBandRows - 1) / kPngBandRows;
    s.bands.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        s.bands[k].y0 = k * kPngBandRows;
        s.bands[k].y1 = std::min(page.height, (k + 1) * kPngBandRows);
    }
    s.next_band_end = s.bands[0].y1;
    for (int i = 0; i < std::clamp(workers, 0, kMaxPngThreads); ++i) {
        try {
            s.workers.emplace_back([&s] { s.work(/*wait=*/true); });
        } catch (const std::system_error&) {
            break;  // fewer workers; finish() deflates what they would have
        }
    }
}

PngGrayStream::~PngGrayStream() {
    Impl& s = *impl_;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.stop = true;
        s.queued = s.taken;  // an abandoned page: no band is started after this
    }
    s.wake.notify_all();
    for (std::thread& t : s.workers) t.join();
}

void PngGrayStream::rows_final(int rows) {
    Impl& s = *impl_;
    if (!s.banded || rows < s.next_band_end || s.finished) return;
    const int n = static_cast<int>(s.bands.size());
    int queue = 0;
    while (queue < n && s.bands[queue].y1 <= rows) ++queue;
    s.next_band_end = queue < n ? s.bands[queue].y1 : s.page.height + 1;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.queued = std::max(s.queued, queue);
    }
    s.wake.notify_all();
}

Expected<std::vector<std::uint8_t>> PngGrayStream::finish() {
    Impl& s = *impl_;
    if (s.finished) return Error{"PngGrayStream::finish called twice"};
    s.finished = true;
    if (!s.banded) return encode_png_gray(s.page, s.options);  // which also names any problem
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.queued = static_cast<int>(s.bands.size());
    }
    s.wake.notify_all();
    s.work(/*wait=*/false);
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.stop = true;
    }
    s.wake.notify_all();
    for (std::thread& t : s.workers) t.join();
    s.workers.clear();
    return s.assemble();
}

Expected<std::vector<std::uint8_t>> PngGrayStream::Impl::assemble() {
    const int n = static_cast<int>(bands.size());
    uLong adler = bands[0].adler;
    for (int k = 0; k < n; ++k) {
        if (!bands[k].ok) return Error{"PNG encoding failed: zlib could not deflate the image"};
        if (k > 0)
            adler = adler32_combine(adler, bands[k].adler, static_cast<z_off_t>(bands[k].length));
    }
    return png_file(page.width, page.height, /*color_type=*/0, options.compression,
                    bands.data(), n, adler);
}

namespace png_detail {

Expected<std::vector<std::uint8_t>> encode_png_igzip(int width, int height,
                                                     std::uint8_t color_type,
                                                     const std::uint8_t* scanlines,
                                                     std::size_t bytes,
                                                     PngCompression compression) {
    Deflater deflater(compression);
    Band band;
    band.y1 = height;
    deflater.deflate(scanlines, bytes, /*history=*/0, /*last=*/true, band);
    if (!band.ok) return Error{"PNG encoding failed: igzip could not deflate the image"};
    return png_file(width, height, color_type, compression, &band, 1, band.adler);
}

}  // namespace png_detail

Expected<std::vector<std::uint8_t>> encode_png_gray(ConstMaskView mask, int threads,
                                                    const PngOptions& options) {
    if (threads <= 1) return encode_png_gray(mask, options);
    PngGrayStream stream(mask, std::min(threads, kMaxPngThreads) - 1, options);
    return stream.finish();
}

}  // namespace bezel
