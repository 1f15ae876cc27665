// bezel/font_face.hpp — a font's bytes and face, read once and shared: what Font, Shaper and the
// glyph rasterizer of one font are all made from, on any number of threads.
//
// A FontFace is immutable shared state: the font bytes (read from a file once, borrowed from the
// caller, or owned jointly with the caller), the face index, a display name for messages, and
// what is parsed from the bytes once and read-only afterwards (the HarfBuzz face every Shaper of
// the face shares). Copying a FontFace copies a shared pointer; every copy is the same face.
//
// Threading: a FontFace may be copied, read and used to make Fonts and Shapers from any number
// of threads at once. The objects made from it (Font::open(face), Shaper::open(face)) are each
// one thread's, and cheap: a Font is a FreeType face over the shared bytes (FT_New_Memory_Face,
// no copy and no second read), a Shaper a HarfBuzz font over the shared HarfBuzz face. So a
// program opens a face once and gives each thread its own Font and Shaper of it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bezel/expected.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

class FontFace;

// Fonts from memory: which face of the bytes, and the name messages give the font.
struct FontMemoryOptions {
    int face_index = 0;             // 0..face count − 1 (collections, TTC/OTC, have several)
    std::string name = "<memory>";  // what errors and Font::file() call the font
};

namespace font_detail {
// One object derived from a face's bytes, made by `make` on the first request for this face and
// shared read-only by every copy of the face afterwards (thread-safe: concurrent first requests
// make it once). bezel's text module keeps its HarfBuzz face here, which the font module does not
// see. `make` may return null (the bytes are not what it needs); null is then kept and returned.
// Only one kind of object is kept per face: every caller must pass the same `make`.
std::shared_ptr<const void> derived_state(const FontFace& face,
                                          std::shared_ptr<const void> (*make)(const FontFace&));
}  // namespace font_detail

class FontFace {
public:
    // Reads a font file (TTF, OTF, TTC/OTC) once. Errors name the file: no such file, a directory,
    // unreadable, larger than kMaxFontBytes, not a font FreeType reads (its reason), face
    // index out of range (0..face count − 1).
    static Expected<FontFace> open(const std::string& file, int face_index = 0);
    // Caller-owned bytes: not copied. `data` must stay valid and unchanged until every FontFace,
    // Font and Shaper made from it (and every copy of them) is destroyed. Errors name
    // `options.name`: empty or null data, more than kMaxFontBytes, not a font (FreeType's
    // reason), face index out of range. Bytes that are not a font give an Error, never a crash.
    static Expected<FontFace> from_memory(const void* data, std::size_t size,
                                          const FontMemoryOptions& options = {});
    // Shared ownership: the bytes live as long as the last face, Font or Shaper made from them.
    // The vector must not be changed while any of them exists. Errors as the borrowing form (a
    // null pointer is "no data").
    static Expected<FontFace> from_memory(std::shared_ptr<const std::vector<std::uint8_t>> bytes,
                                          const FontMemoryOptions& options = {});

    // The file it was read from, or FontMemoryOptions::name for a font from memory: what every
    // message about the font starts with.
    const std::string& name() const;
    bool from_file() const;   // true for open(), false for from_memory()
    int face_index() const;
    int face_count() const;   // faces in the bytes (a collection has more than one)
    const std::uint8_t* data() const;   // the font bytes (the whole file for a collection)
    std::size_t size() const;
    // Identifies the face: equal for copies of one FontFace, different for faces opened or made
    // separately (even of the same file), never reused by another face while the process runs.
    std::uint64_t id() const;

private:
    struct Impl;
    friend std::shared_ptr<const void> font_detail::derived_state(
        const FontFace&, std::shared_ptr<const void> (*)(const FontFace&));
    explicit FontFace(std::shared_ptr<Impl> impl);
    // Both from_memory forms: `owner` null for borrowed bytes.
    static Expected<FontFace> from_memory(const void* data, std::size_t size,
                                          const FontMemoryOptions& options,
                                          std::shared_ptr<const std::vector<std::uint8_t>> owner);
    std::shared_ptr<Impl> impl_;
};

}  // namespace bezel
#pragma GCC visibility pop
