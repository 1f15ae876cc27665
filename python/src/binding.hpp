// python/src/binding.hpp — what the two translation units of the `bezel._bezel` extension share:
// how bezel's errors become Python exceptions, how C++ buffers become numpy arrays without a
// copy, and the immutable Path object.
//
// The extension sees bezel through its public headers only (lib/include/bezel), as any consumer.
// Its Python surface is private (`bezel._bezel`): python/bezel/__init__.py checks and documents
// the arguments and builds the public objects; this layer still checks everything it is given,
// so a direct call with bad values raises, never crashes.
//
// Threading: every call that shapes, rasterizes or encodes releases the GIL for that work. What
// such a call reads while the GIL is released is either copied first (text, options) or immutable
// (a Path, a font's bytes), so another Python thread cannot change it underneath.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/geometry.hpp"
#include "bezel/path.hpp"

namespace bezel::python {

namespace py = pybind11;

// bezel's own Error (a font it cannot read, a layout it refuses): raised as bezel.Error with the
// library's message, which already names the input.
class Failure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The value of `result`, or Failure with its message.
template <typename T>
T take(Expected<T>&& result) {
    if (!result) throw Failure(result.error().message);
    return std::move(*result);
}
inline void check(const Status& status) {
    if (!status) throw Failure(status.error().message);
}

// The category of bezel.MissingGlyphWarning (set by the module's init).
PyObject* missing_glyph_warning();
// Issues `message` as a warning of `category` (Python's warnings machinery: it may be filtered,
// or raised when the filters turn warnings into errors). Needs the GIL.
void warn(PyObject* category, const std::string& message);

// A numpy uint8 array of `shape` over `pixels`, which the array then owns (a capsule frees it
// when the array and every view of it are gone): no copy. Needs the GIL.
py::array_t<std::uint8_t> adopt_pixels(std::vector<std::uint8_t>&& pixels,
                                       std::vector<py::ssize_t> shape);

// Text for the library: a str (encoded to UTF-8; lone surrogates raise UnicodeEncodeError) or
// bytes (taken as UTF-8, which the library checks and names the bad byte of). Copied, so the GIL
// can be released while it is used. Anything else is a TypeError naming `what`.
std::string utf8_text(const py::handle& text, const char* what);

// An affine map from a 6-tuple (a, b, c, d, e, f): SVG's matrix(a b c d e f), x' = a·x + c·y + e,
// y' = b·x + d·y + f. None is the identity. Non-finite entries are a ValueError.
Affine affine_from(const py::handle& transform);

// The immutable path object behind bezel.Path: built once (SVG data, or by the library) and never
// changed, so any thread may read it with the GIL released.
struct PathObject {
    Path path;
};

// Python-visible (kind, points) segments of `path`: kind "line", "quad" or "cubic"; points a tuple
// of (x, y) tuples (2, 3 or 4 of them), including the closing line of a closed contour.
py::list segments_of(const Path& path);
// (x0, y0, x1, y1), or None for a rectangle that is empty.
py::object rect_tuple(const Rect& r);

// The text and glyph calls of bezel.Font (font.cpp).
void bind_font(py::module_& m);

}  // namespace bezel::python
