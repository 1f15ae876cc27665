// encode_png_gray(mask, threads) and PngGrayStream: a PNG written by hand around zlib, so the
// deflating can be split across threads (libpng deflates one stream on the calling thread only)
// and can start on the top of a page while its bottom is still being drawn.
//
// PNG layout (ISO/IEC 15948): the 8-byte signature, then chunks of {length (4 bytes, big
// endian), type (4), data, CRC-32 of type and data}: IHDR (width, height, bit depth 8, colour
// type 0 = gray, compression 0, filter 0, interlace 0), one IDAT holding the zlib stream of the
// scanlines (each row prefixed by its filter byte, 0 = none, as the libpng writer uses), IEND.
//
// The zlib stream (RFC 1950) is a 2-byte header, raw deflate data (RFC 1951) and the Adler-32 of
// the uncompressed bytes. Band k (rows [64k, 64k + 64)) is deflated raw on its own; every band
// but the last ends with Z_SYNC_FLUSH (a non-final empty stored block, so the next band's blocks
// start on a byte boundary) and the last with Z_FINISH (the final block), so their concatenation
// is one valid deflate stream. The Adler-32s of the bands are joined with adler32_combine.
//
// Why 64-row bands whatever the thread count: a worker can start while a page of text is still
// drawn (a 16 px line of text is ~19 rows), and the bytes do not depend on the core count. The
// price is size, since each band starts with an empty history: on the 716×2361 benchmark page
// 299 587 bytes against 265 362 for one stream (+13 %). Priming each band with the rows above
// it (deflateSetDictionary) won most of that back (16 rows: 276 239 bytes) but cost 8–46 % more
// instructions (valgrind, 16–45 rows), and this writer exists for speed.
#include <zlib.h>

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <mutex>
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

// One z_stream, reused from band to band (deflateReset keeps its ~300 KB of tables).
class Deflater {
public:
    Deflater() { ok_ = deflateInit2(&z_, kLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) == Z_OK; }
    ~Deflater() {
        if (ok_) deflateEnd(&z_);
    }
    Deflater(const Deflater&) = delete;
    Deflater& operator=(const Deflater&) = delete;

    void run(ConstMaskView mask, bool last, Band& band) {
        if (!ok_ || deflateReset(&z_) != Z_OK) return;
        z_stream& z = z_;
        const uLong raw =
            static_cast<uLong>(band.y1 - band.y0) * (static_cast<uLong>(mask.width) + 1);
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
        band.ok = ok;
    }

private:
    z_stream z_{};
    bool ok_ = false;
};

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

// The bands' shared state: bands [0, queued) may be taken, [0, taken) have been.
struct PngGrayStream::Impl {
    ConstMaskView page;
    bool banded = false;  // false: finish() is the one-thread libpng writer
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
        Deflater deflater;
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

PngGrayStream::PngGrayStream(ConstMaskView page, int workers) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.page = page;
    s.banded = page.data != nullptr && page.width > 0 && page.width <= kMaxImageDim &&
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
    if (!s.banded) return encode_png_gray(s.page);  // which also names any problem with the page
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
    const ConstMaskView& mask = page;
    const int n = static_cast<int>(bands.size());
    uLong adler = bands[0].adler;
    std::size_t total = 0;
    for (int k = 0; k < n; ++k) {
        if (!bands[k].ok) return Error{"PNG encoding failed: zlib could not deflate the image"};
        if (k > 0)
            adler = adler32_combine(adler, bands[k].adler, static_cast<z_off_t>(bands[k].length));
        total += bands[k].deflated.size();
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
        for (const Band& b : bands) o.insert(o.end(), b.deflated.begin(), b.deflated.end());
        put32(o, static_cast<std::uint32_t>(adler));
    });
    chunk(out, "IEND", [](std::vector<std::uint8_t>&) {});
    return out;
}

Expected<std::vector<std::uint8_t>> encode_png_gray(ConstMaskView mask, int threads) {
    if (threads <= 1) return encode_png_gray(mask);
    PngGrayStream stream(mask, std::min(threads, kMaxPngThreads) - 1);
    return stream.finish();
}

}  // namespace bezel
