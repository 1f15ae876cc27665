// python/src/module.cpp — the `bezel._bezel` extension: its errors, the Path object, fill,
// PNG encoding and colour parsing; font.cpp binds the fonts. binding.hpp states the rules both
// files follow (errors, the GIL, what is copied before the GIL is released).
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include "binding.hpp"
#include "bezel/flatten.hpp"
#include "bezel/font.hpp"
#include "bezel/image.hpp"
#include "bezel/limits.hpp"
#include "bezel/raster.hpp"
#include "bezel/text_renderer.hpp"

namespace bezel::python {

namespace {

PyObject* g_missing_glyph_warning = nullptr;

// The array's raw layout, after checking it is a uint8 array; `what` names it in messages.
struct ByteArray {
    py::array array;
    py::ssize_t ndim = 0;
    const py::ssize_t* shape = nullptr;
    const py::ssize_t* strides = nullptr;
};

ByteArray byte_array(const py::handle& object, const char* what) {
    if (!py::isinstance<py::array>(object))
        throw py::type_error(std::string(what) + ": expected a numpy array, got " +
                             std::string(py::str(py::type::handle_of(object).attr("__name__"))));
    auto array = py::reinterpret_borrow<py::array>(object);
    const py::dtype type = array.dtype();
    if (!(type.kind() == 'u' && type.itemsize() == 1))
        throw py::type_error(std::string(what) + ": expected dtype uint8, got " +
                             std::string(py::str(array.dtype())));
    return {array, array.ndim(), array.shape(), array.strides()};
}

// Path ------------------------------------------------------------------------------------------

PathObject path_from_svg(const std::string& data) {
    return PathObject{take(parse_svg_path(data))};
}

py::object path_bounds(const PathObject& self, const py::object& transform) {
    const Affine m = affine_from(transform);
    return rect_tuple(m == Affine::identity() ? self.path.bounds()
                                              : self.path.transformed(m).bounds());
}

PathObject path_transformed(const PathObject& self, const py::object& transform) {
    const Affine m = affine_from(transform);
    PathObject out{self.path.transformed(m)};
    if (!out.path.is_finite())
        throw py::value_error("transform: the transformed path has non-finite points");
    return out;
}

// fill ------------------------------------------------------------------------------------------

FillRule fill_rule(const std::string& name) {
    if (name == "nonzero") return FillRule::NonZero;
    if (name == "evenodd") return FillRule::EvenOdd;
    throw py::value_error("rule: '" + name + "': expected 'nonzero' or 'evenodd'");
}

// One Rasterizer per thread: its scratch grows to the largest fill and is then reused, so
// steady-state fills allocate only their result.
Rasterizer& thread_rasterizer() {
    thread_local Rasterizer rasterizer;
    return rasterizer;
}

py::array fill(const PathObject& path, long long width, long long height,
               const py::object& transform, const std::string& rule, double tolerance,
               const py::object& out) {
    for (auto [name, value] : {std::pair{"width", width}, std::pair{"height", height}})
        if (value < 0 || value > kMaxBitmapDim)
            throw py::value_error(std::string(name) + ": " + std::to_string(value) +
                                  " is outside 0.." + std::to_string(kMaxBitmapDim) + " pixels");
    if (!(std::isfinite(tolerance) && tolerance >= kMinFlattenTolerancePx))
        throw py::value_error("tolerance: must be a finite number >= " +
                              std::to_string(kMinFlattenTolerancePx) + " pixels");
    FillOptions options;
    options.rule = fill_rule(rule);
    options.flatten.tolerance_px = tolerance;
    const Affine m = affine_from(transform);
    const int w = static_cast<int>(width), h = static_cast<int>(height);

    py::array target;
    MaskView view;
    if (out.is_none()) {
        py::array_t<std::uint8_t> made({static_cast<py::ssize_t>(h), static_cast<py::ssize_t>(w)});
        view = {made.mutable_data(), w, h, static_cast<std::ptrdiff_t>(w)};
        target = std::move(made);
    } else {
        ByteArray a = byte_array(out, "out");
        if (a.ndim != 2 || a.shape[0] != h || a.shape[1] != w)
            throw py::value_error("out: expected shape (" + std::to_string(h) + ", " +
                                  std::to_string(w) + "), got " +
                                  std::string(py::str(out.attr("shape"))));
        if (!a.array.writeable()) throw py::value_error("out: the array is read-only");
        // Rows may be apart by any stride (a sub-rectangle of an atlas, bottom-up memory), but
        // the pixels of a row must be adjacent bytes: the rasterizer writes rows as runs.
        if (w > 1 && a.strides[1] != 1)
            throw py::value_error("out: the pixels of a row must be contiguous (strides[1] == 1), "
                                  "got strides " + std::string(py::str(out.attr("strides"))));
        view = {static_cast<std::uint8_t*>(a.array.mutable_data()), w, h,
                static_cast<std::ptrdiff_t>(a.strides[0])};
        target = a.array;
    }
    Status status = ok_status();
    {
        py::gil_scoped_release release;
        status = thread_rasterizer().fill_path(path.path, m, view, options);
    }
    check(status);
    return target;
}

// encode_png --------------------------------------------------------------------------------------

PngCompression png_compression(const std::string& name) {
    if (name == "default") return PngCompression::Default;
    if (name == "fast") return PngCompression::Fast;
    if (name == "small") return PngCompression::Small;
    throw py::value_error("compression: '" + name + "': expected 'default', 'fast' or 'small'");
}

py::bytes encode_png_array(const py::object& object, const std::string& compression) {
    PngOptions options;
    options.compression = png_compression(compression);
    ByteArray a = byte_array(object, "array");
    const bool gray = a.ndim == 2;
    if (!(gray || (a.ndim == 3 && (a.shape[2] == 3 || a.shape[2] == 4))))
        throw py::value_error("array: expected shape (H, W) gray, (H, W, 3) RGB or (H, W, 4) "
                              "RGBA, got " + std::string(py::str(object.attr("shape"))));
    for (int k = 0; k < 2; ++k)
        if (a.shape[k] < 1 || a.shape[k] > kMaxImageDim)
            throw py::value_error("array: " + std::string(k == 0 ? "height " : "width ") +
                                  std::to_string(a.shape[k]) + " is outside 1.." +
                                  std::to_string(kMaxImageDim) + " pixels");
    const int h = static_cast<int>(a.shape[0]), w = static_cast<int>(a.shape[1]);
    const std::uint8_t* base = static_cast<const std::uint8_t*>(a.array.data());
    Expected<std::vector<std::uint8_t>> png = std::vector<std::uint8_t>();
    if (gray && a.strides[1] == 1) {
        const ConstMaskView mask(base, w, h, static_cast<std::ptrdiff_t>(a.strides[0]));
        py::gil_scoped_release release;
        png = encode_png_gray(mask, options);
    } else {
        // Any strides: the pixels are gathered into an Image (the colour encoder's input).
        const int channels = gray ? 1 : static_cast<int>(a.shape[2]);
        const py::ssize_t sy = a.strides[0], sx = a.strides[1], sc = gray ? 0 : a.strides[2];
        py::gil_scoped_release release;
        Image image(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::uint8_t* p = base + y * sy + x * sx;
                Rgba8& q = image.at(x, y);
                if (channels == 1) {
                    q = {p[0], p[0], p[0], 255};
                } else {
                    q = {p[0], p[sc], p[2 * sc],
                         channels == 4 ? p[3 * sc] : static_cast<std::uint8_t>(255)};
                }
            }
        const PngColor color = channels == 1 ? PngColor::Gray
                               : channels == 3 ? PngColor::Rgb
                                               : PngColor::Rgba;
        png = encode_png(image, color, options);
    }
    const std::vector<std::uint8_t> bytes = take(std::move(png));
    return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

py::tuple color_tuple(const std::string& text) {
    auto parsed = parse_color(text);
    if (!parsed) throw py::value_error(parsed.error().message);
    return py::make_tuple(parsed->r, parsed->g, parsed->b, parsed->a);
}

}  // namespace

// Shared helpers (binding.hpp) -------------------------------------------------------------------

PyObject* missing_glyph_warning() { return g_missing_glyph_warning; }

void warn(PyObject* category, const std::string& message) {
    if (PyErr_WarnEx(category, message.c_str(), 2) != 0) throw py::error_already_set();
}

py::array_t<std::uint8_t> adopt_pixels(std::vector<std::uint8_t>&& pixels,
                                       std::vector<py::ssize_t> shape) {
    auto owned = std::make_unique<std::vector<std::uint8_t>>(std::move(pixels));
    std::uint8_t* data = owned->data();
    py::capsule owner(owned.get(), [](void* p) {
        delete static_cast<std::vector<std::uint8_t>*>(p);
    });
    owned.release();  // the capsule owns it now
    std::vector<py::ssize_t> strides(shape.size());
    py::ssize_t step = 1;
    for (std::size_t k = shape.size(); k-- > 0;) {
        strides[k] = step;
        step *= shape[k];
    }
    return py::array_t<std::uint8_t>(shape, strides, data, owner);
}

std::string utf8_text(const py::handle& text, const char* what) {
    if (PyUnicode_Check(text.ptr())) {
        Py_ssize_t size = 0;
        const char* data = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
        if (!data) throw py::error_already_set();
        return std::string(data, static_cast<std::size_t>(size));
    }
    if (PyBytes_Check(text.ptr()))
        return std::string(PyBytes_AS_STRING(text.ptr()),
                           static_cast<std::size_t>(PyBytes_GET_SIZE(text.ptr())));
    throw py::type_error(std::string(what) + ": expected str or bytes, got " +
                         std::string(py::str(py::type::handle_of(text).attr("__name__"))));
}

Affine affine_from(const py::handle& transform) {
    if (transform.is_none()) return Affine::identity();
    if (!py::isinstance<py::sequence>(transform) || py::isinstance<py::str>(transform) ||
        py::len(transform) != 6)
        throw py::type_error("transform: expected a sequence of 6 numbers (a, b, c, d, e, f)");
    auto seq = py::reinterpret_borrow<py::sequence>(transform);
    double v[6];
    for (int k = 0; k < 6; ++k) {
        py::object item = seq[static_cast<py::size_t>(k)];
        if (!PyNumber_Check(item.ptr()) || PyBool_Check(item.ptr()))
            throw py::type_error("transform: entry " + std::to_string(k) + " is not a number");
        v[k] = item.cast<double>();
        if (!std::isfinite(v[k]))
            throw py::value_error("transform: entry " + std::to_string(k) + " is not finite");
    }
    return Affine{v[0], v[1], v[2], v[3], v[4], v[5]};
}

py::object rect_tuple(const Rect& r) {
    if (r.is_empty()) return py::none();
    return py::make_tuple(r.x0, r.y0, r.x1, r.y1);
}

py::list segments_of(const Path& path) {
    py::list out;
    for (const PathSeg& s : path.segments()) {
        const int n = s.kind == SegKind::Line ? 2 : s.kind == SegKind::Quad ? 3 : 4;
        py::tuple points(n);
        for (int k = 0; k < n; ++k) points[k] = py::make_tuple(s.p[k].x, s.p[k].y);
        const char* kind = n == 2 ? "line" : n == 3 ? "quad" : "cubic";
        out.append(py::make_tuple(kind, points));
    }
    return out;
}

}  // namespace bezel::python

using namespace bezel::python;
namespace b = bezel;

PYBIND11_MODULE(_bezel, m) {
    m.doc() = "bezel's C++ library for Python (private: import bezel)";
    m.attr("version") = BEZEL_PROJECT_VERSION_STRING;
    py::register_exception<Failure>(m, "Error");
    // Kept for the life of the process (the module's attribute holds another reference).
    g_missing_glyph_warning =
        PyErr_NewException("bezel._bezel.MissingGlyphWarning", PyExc_UserWarning, nullptr);
    if (!g_missing_glyph_warning) throw py::error_already_set();
    m.attr("MissingGlyphWarning") = py::handle(g_missing_glyph_warning);
    // A value of the wrong type met while reading an argument (an item of a list, a tuple's entry)
    // is the caller's TypeError, not pybind11's default RuntimeError.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const py::cast_error& e) {
            PyErr_SetString(PyExc_TypeError, e.what());
        }
    });

    // The library's limits, each stated once in bezel/limits.hpp (and the headers beside it), for
    // the Python layer's argument checks.
    py::dict limits;
    limits["max_font_size_px"] = b::kMaxFontSizePx;
    limits["max_bitmap_dim"] = b::kMaxBitmapDim;
    limits["max_image_dim"] = b::kMaxImageDim;
    limits["max_text_bytes"] = b::kMaxTextBytes;
    limits["max_face_index"] = b::kMaxFaceIndex;
    limits["max_synthetic_bold"] = b::kMaxSyntheticBold;
    limits["max_synthetic_slant"] = b::kMaxSyntheticSlant;
    limits["max_collection_fonts"] = b::kMaxCollectionFonts;
    limits["min_text_gamma"] = b::kMinTextGamma;
    limits["max_text_gamma"] = b::kMaxTextGamma;
    limits["max_text_contrast"] = b::kMaxTextContrast;
    limits["default_text_gamma"] = b::kDefaultTextGamma;
    limits["default_text_contrast"] = b::kDefaultTextContrast;
    limits["default_raster_tolerance_px"] = b::kDefaultRasterTolerancePx;
    limits["min_flatten_tolerance_px"] = b::kMinFlattenTolerancePx;
    limits["max_glyph_offset_px"] = b::kMaxGlyphOffsetPx;
    m.attr("limits") = limits;

    py::class_<PathObject>(m, "Path")
        .def(py::init<>())
        .def_static("from_svg", &path_from_svg, py::arg("data"))
        .def("svg", [](const PathObject& p, int precision) {
                 if (precision < 1 || precision > 17)
                     throw py::value_error("precision: " + std::to_string(precision) +
                                           " is outside 1..17 significant digits");
                 return b::to_svg_path(p.path, precision);
             }, py::arg("precision") = 17)
        .def("bounds", &path_bounds, py::arg("transform") = py::none())
        .def("control_box", [](const PathObject& p) { return rect_tuple(p.path.control_box()); })
        .def("transformed", &path_transformed, py::arg("transform"))
        .def("segments", [](const PathObject& p) { return segments_of(p.path); })
        .def("segment_count", [](const PathObject& p) { return p.path.segment_count(); })
        .def("contour_count", [](const PathObject& p) { return p.path.contour_count(); })
        .def("signed_area", [](const PathObject& p) { return p.path.signed_area(); })
        .def("is_empty", [](const PathObject& p) { return p.path.empty(); })
        .def("equals", [](const PathObject& p, const PathObject& o) { return p.path == o.path; });

    m.def("fill", &fill, py::arg("path"), py::arg("width"), py::arg("height"),
          py::arg("transform"), py::arg("rule"), py::arg("tolerance"), py::arg("out"));
    m.def("encode_png", &encode_png_array, py::arg("array"), py::arg("compression"));
    m.def("parse_color", &color_tuple, py::arg("text"));

    bind_font(m);
}
