// tests/fuzz/fuzz_reader.hpp — turns a fuzzer's bytes into the values bezel's APIs take.
//
// Every read is total: past the end of the input it yields zeros, so a target never has to
// check sizes, and a short input still builds a (small) valid call. Coordinates come mostly from
// small integers and halves (so the fuzzer finds coincidences, tangencies and degenerate curves
// easily), sometimes from the values that break numerics: NaN, ±inf, 1e30, 2^50, denormals and
// raw 64-bit patterns.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include <cstdio>
#include <cstdlib>

#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel::fuzz {

class FuzzReader {
public:
    FuzzReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    bool empty() const { return pos_ >= size_; }
    std::size_t remaining() const { return empty() ? 0 : size_ - pos_; }

    std::uint8_t byte() { return empty() ? 0 : data_[pos_++]; }
    std::uint16_t u16() { return static_cast<std::uint16_t>(byte() | (byte() << 8)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(u16()) | (std::uint32_t{u16()} << 16); }
    std::uint64_t u64() { return static_cast<std::uint64_t>(u32()) | (std::uint64_t{u32()} << 32); }
    bool flag() { return (byte() & 1) != 0; }
    // An integer in [0, n) (n > 0).
    std::size_t below(std::size_t n) { return n == 0 ? 0 : u16() % n; }

    // A double with the distribution described at the top of the file.
    double number() {
        const std::uint8_t kind = byte();
        if (kind < 160) return (static_cast<int>(byte()) - 128) * 0.5;  // −64 … 63.5 by halves
        if (kind < 200) return static_cast<std::int16_t>(u16()) / 64.0;  // 1/64 steps, ±512
        switch (kind % 12) {
            case 0: return std::numeric_limits<double>::quiet_NaN();
            case 1: return std::numeric_limits<double>::infinity();
            case 2: return -std::numeric_limits<double>::infinity();
            case 3: return 1e30;
            case 4: return -1e30;
            case 5: return 1125899906842624.0;  // 2^50, flatten's coordinate wall
            case 6: return std::numeric_limits<double>::denorm_min();
            case 7: return std::numeric_limits<double>::max();
            case 8: return 1e-300;
            case 9: return static_cast<std::int32_t>(u32()) * 1e-3;
            default: {
                std::uint64_t bits = u64();
                double d;
                std::memcpy(&d, &bits, sizeof d);
                return d;
            }
        }
    }
    // A number that is finite and moderate most of the time (for sizes and tolerances).
    double positive(double typical) {
        const std::uint8_t kind = byte();
        if (kind < 200) return typical * (1 + kind) / 64.0;
        return number();
    }
    Point point() {
        double x = number();
        return {x, number()};
    }
    // The rest of the input as a string, at most `max` bytes.
    std::string rest(std::size_t max) {
        std::size_t n = remaining() < max ? remaining() : max;
        std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
        pos_ += n;
        return s;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

// A path of up to `max_verbs` builder calls (moves, lines, quads, cubics, closes in any order).
inline Path read_path(FuzzReader& in, std::size_t max_verbs) {
    Path path;
    const std::size_t n = in.below(max_verbs + 1);
    for (std::size_t i = 0; i < n && !in.empty(); ++i) {
        switch (in.byte() % 5) {
            case 0: path.move_to(in.point()); break;
            case 1: path.line_to(in.point()); break;
            case 2: { Point c = in.point(); path.quad_to(c, in.point()); break; }
            case 3: {
                Point c1 = in.point(), c2 = in.point();
                path.cubic_to(c1, c2, in.point());
                break;
            }
            default: path.close(); break;
        }
    }
    return path;
}

// A property a fuzz target asserts: on failure, say which and abort so libFuzzer saves the input.
#define BEZEL_FUZZ_CHECK(cond)                                                            \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            std::fprintf(stderr, "%s:%d: fuzz property failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                                 \
        }                                                                                 \
    } while (0)

}  // namespace bezel::fuzz
