// python/src/font.cpp — bezel.Font's engine (`_bezel.FontCore`): a list of font faces (the font
// and its fallbacks) read once, and a pool of per-thread renderers over them, so that one Font
// shared by many Python threads renders on all of them at once with the GIL released.
//
// Why a pool: a TextRenderer (its FreeType faces, HarfBuzz fonts and glyph cache) must be used by
// one thread at a time (text_renderer.hpp). A call leases an idle renderer, or makes one from the
// shared faces (no file is read again: font_face.hpp), and gives it back afterwards; at most
// kMaxIdleWorkers are kept between calls.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "binding.hpp"
#include "bezel/color_glyph.hpp"
#include "bezel/font.hpp"
#include "bezel/font_collection.hpp"
#include "bezel/font_face.hpp"
#include "bezel/glyph.hpp"
#include "bezel/image.hpp"
#include "bezel/layout.hpp"
#include "bezel/limits.hpp"
#include "bezel/shape.hpp"
#include "bezel/text_renderer.hpp"

namespace bezel::python {

namespace {

// Idle renderers a Font keeps for the next calls: one per thread that renders with it at once, up
// to this many (each holds its faces' FreeType and HarfBuzz objects and a glyph cache of up to
// kDefaultGlyphCacheBytes). Threads beyond it still render; their renderers are dropped after the
// call and made again (a few milliseconds) by the next.
constexpr std::size_t kMaxIdleWorkers = 16;

// Glyph outlines a renderer keeps for text_path (Worker::outlines): a few scripts' worth at a
// few sizes (Latin text at 3 sizes in 2 fonts is ~600); a glyph path is ~1-5 KB, so at most a
// few MB a renderer. When full it is emptied and refilled.
constexpr std::size_t kMaxCachedOutlines = 2048;

static_assert(sizeof(Rgba8) == 4, "an Image row is width × 4 bytes, R G B A");

// Reading the options dict the Python layer fills (python/bezel/_font.py): every key is optional
// here (the library's default applies), and a value of the wrong type is a TypeError naming it.
template <typename T>
T option(const py::dict& d, const char* key, T fallback) {
    if (!d.contains(key)) return fallback;
    py::object value = d[key];
    if (value.is_none()) return fallback;
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(std::string(key) + ": unexpected type " +
                             std::string(py::str(py::type::handle_of(value).attr("__name__"))));
    }
}

std::uint8_t channel(const py::handle& v, const char* key) {
    if (!PyLong_Check(v.ptr()) || PyBool_Check(v.ptr()))
        throw py::type_error(std::string(key) + ": colour channels must be ints 0..255");
    const long long c = v.cast<long long>();
    if (c < 0 || c > 255)
        throw py::value_error(std::string(key) + ": channel " + std::to_string(c) +
                              " is outside 0..255");
    return static_cast<std::uint8_t>(c);
}

// A colour as the Python layer passes it: (r, g, b, a), bytes 0..255.
Rgba8 colour_of(const py::handle& value, const char* key) {
    if (!py::isinstance<py::tuple>(value) || py::len(value) != 4)
        throw py::type_error(std::string(key) + ": expected an (r, g, b, a) tuple");
    auto t = py::reinterpret_borrow<py::tuple>(value);
    return {channel(t[0], key), channel(t[1], key), channel(t[2], key), channel(t[3], key)};
}
Rgba8 colour(const py::dict& d, const char* key, Rgba8 fallback) {
    if (!d.contains(key) || d[key].is_none()) return fallback;
    return colour_of(d[key], key);
}

Hinting hinting_named(const std::string& name) {
    if (name == "none") return Hinting::None;
    if (name == "light") return Hinting::Light;
    if (name == "full") return Hinting::Full;
    if (name == "auto") return Hinting::Auto;
    throw py::value_error("hinting: '" + name + "': expected 'none', 'light', 'full' or 'auto'");
}

Direction direction_named(const std::string& name) {
    if (name == "auto") return Direction::Auto;
    if (name == "ltr") return Direction::LeftToRight;
    if (name == "rtl") return Direction::RightToLeft;
    if (name == "ttb") return Direction::TopToBottom;
    if (name == "btt") return Direction::BottomToTop;
    throw py::value_error("direction: '" + name + "': expected 'ltr', 'rtl', 'ttb', 'btt' or "
                          "'auto'");
}

Align align_named(const std::string& name) {
    if (name == "start") return Align::Start;
    if (name == "center") return Align::Center;
    if (name == "end") return Align::End;
    throw py::value_error("align: '" + name + "': expected 'start', 'center' or 'end'");
}

// The colour-glyph options shared by render() and glyph(): color (on/off), palette, and
// custom_palette as a list of (index, (r, g, b, a)).
GlyphColorOptions color_options(const py::dict& d) {
    GlyphColorOptions c;
    c.enabled = option<bool>(d, "color", true);
    const long long palette = option<long long>(d, "palette", 0);
    if (palette < 0 || palette > 0xFFFF)
        throw py::value_error("palette: " + std::to_string(palette) + " is outside 0..65535");
    c.palette.palette = static_cast<int>(palette);
    if (d.contains("custom_palette") && !d["custom_palette"].is_none()) {
        for (const py::handle item : py::reinterpret_borrow<py::iterable>(d["custom_palette"])) {
            if (!py::isinstance<py::tuple>(item) || py::len(item) != 2)
                throw py::type_error("custom_palette: expected (index, colour) pairs");
            auto pair = py::reinterpret_borrow<py::tuple>(item);
            const long long index = pair[0].cast<long long>();
            if (index < 0 || index > 0xFFFF)
                throw py::value_error("custom_palette: index " + std::to_string(index) +
                                      " is outside 0..65535");
            c.palette.custom.push_back(
                {static_cast<int>(index), colour_of(pair[1], "custom_palette")});
        }
    }
    return c;
}

struct RenderRequest {
    TextRenderOptions options;
    bool strict = false;
};

RenderRequest render_request(const py::dict& d, double default_size, Hinting default_hinting) {
    RenderRequest r;
    TextRenderOptions& o = r.options;
    o.shape.size_px = option<double>(d, "size", default_size);
    const std::string features = option<std::string>(d, "features", "");
    auto parsed = parse_features(features);
    if (!parsed) throw py::value_error("features: " + parsed.error().message);
    o.shape.features = std::move(*parsed);
    o.shape.direction = direction_named(option<std::string>(d, "direction", "auto"));
    o.shape.script = option<std::string>(d, "script", "");
    if (!o.shape.script.empty())
        if (Status s = check_script_tag(o.shape.script); !s)
            throw py::value_error("script: " + s.error().message);
    o.shape.language = option<std::string>(d, "language", "");
    if (!o.shape.language.empty())
        if (Status s = check_language_tag(o.shape.language); !s)
            throw py::value_error("language: " + s.error().message);
    o.shape.bold = option<double>(d, "bold", 0.0);
    o.layout.width_px = option<double>(d, "width", 0.0);
    o.layout.margin_px = option<double>(d, "margin", 0.0);
    o.layout.line_height = option<double>(d, "line_height", 1.0);
    o.layout.align = align_named(option<std::string>(d, "align", "start"));
    const std::string lcd = option<std::string>(d, "lcd", "");
    if (!lcd.empty() && lcd != "rgb" && lcd != "bgr")
        throw py::value_error("lcd: '" + lcd + "': expected 'rgb', 'bgr' or None");
    o.format = lcd.empty() ? CoverageFormat::Gray : CoverageFormat::Lcd;
    o.lcd_order = lcd == "bgr" ? LcdOrder::Bgr : LcdOrder::Rgb;
    if (d.contains("hinting") && !d["hinting"].is_none())
        o.hinting = hinting_named(option<std::string>(d, "hinting", "none"));
    else
        o.hinting = default_hinting;
    o.slant = option<double>(d, "slant", 0.0);
    o.foreground = colour(d, "foreground", o.foreground);
    o.background = colour(d, "background", o.background);
    const std::string rendering = option<std::string>(d, "rendering", "perceptual");
    if (rendering == "perceptual")
        o.coverage.rendering = TextRendering::Perceptual;
    else if (rendering == "linear")
        o.coverage.rendering = TextRendering::Linear;
    else
        throw py::value_error("rendering: '" + rendering + "': expected 'perceptual' or 'linear'");
    o.coverage.gamma = option<double>(d, "gamma", kDefaultTextGamma);
    o.coverage.contrast = option<double>(d, "contrast", kDefaultTextContrast);
    o.color = color_options(d);
    r.strict = option<bool>(d, "strict", false);
    return r;
}

enum class Mode { Auto, Gray, Rgba };
Mode mode_named(const std::string& name) {
    if (name == "auto") return Mode::Auto;
    if (name == "gray") return Mode::Gray;
    if (name == "rgba") return Mode::Rgba;
    throw py::value_error("mode: '" + name + "': expected 'auto', 'gray' or 'rgba'");
}

bool opaque_gray(Rgba8 c) { return c.r == c.g && c.g == c.b && c.a == 255; }

// "U+00E9 'é'"; control characters and spaces as their code point alone.
std::string describe_character(char32_t cp) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
    std::string text = buf;
    if (cp <= 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0)) return text;
    std::string utf8;
    append_utf8(utf8, cp);
    return text + " '" + utf8 + "'";
}

std::string font_names(const FontCollection& fonts) {
    std::string out;
    for (std::size_t i = 0; i < fonts.size(); ++i) out += (i > 0 ? ", " : "") + fonts.source(i).file;
    return out;
}

// Appends `src` mapped by `m` to `dst`, verb by verb (the builder keeps its invariants).
void append_path(Path& dst, const Path& src, const Affine& m) {
    const std::vector<Point>& p = src.points();
    std::size_t i = 0;
    for (Verb v : src.verbs()) {
        switch (v) {
            case Verb::Move: dst.move_to(m * p[i]); i += 1; break;
            case Verb::Line: dst.line_to(m * p[i]); i += 1; break;
            case Verb::Quad: dst.quad_to(m * p[i], m * p[i + 1]); i += 2; break;
            case Verb::Cubic: dst.cubic_to(m * p[i], m * p[i + 1], m * p[i + 2]); i += 3; break;
            case Verb::Close: dst.close(); break;
        }
    }
}

// A Mask or an Image moved into a numpy array that owns it (no copy).
template <typename Owner>
py::array_t<std::uint8_t> adopt(Owner&& value, std::vector<py::ssize_t> shape) {
    auto owned = std::make_unique<Owner>(std::move(value));
    std::uint8_t* data = owned->view().data;
    std::vector<py::ssize_t> strides(shape.size());
    py::ssize_t step = 1;
    for (std::size_t k = shape.size(); k-- > 0;) {
        strides[k] = step;
        step *= shape[k];
    }
    py::capsule owner(owned.get(), [](void* p) { delete static_cast<Owner*>(p); });
    owned.release();  // the capsule owns it now
    return py::array_t<std::uint8_t>(shape, strides, data, owner);
}

struct Source {
    FontFace face;
    std::vector<VariationSetting> variations;
};

// One thread's renderer over the font list, and a glyph rasterizer per font of it (made on first
// use; a rasterizer shares its font's face and variations, glyph.hpp).
struct Worker {
    TextRenderer renderer;
    std::vector<std::unique_ptr<GlyphRasterizer>> rasterizers;
    std::size_t warnings_reported = 0;   // of renderer.fonts().warnings()

    // text_path's glyph outlines as placed (scaled, hinted, slanted), so that a glyph is loaded
    // from FreeType once, not on every call that draws it. They hold for the call options'
    // variation settings `outlines_variations` (the fonts' own are fixed): other settings
    // empty the cache first. At most kMaxCachedOutlines.
    struct OutlineKey {
        std::uint16_t font;
        GlyphId gid;
        double size_px;
        Hinting hinting;
        double slant;
        bool operator<(const OutlineKey& o) const {
            return std::tie(font, gid, size_px, hinting, slant) <
                   std::tie(o.font, o.gid, o.size_px, o.hinting, o.slant);
        }
    };
    std::map<OutlineKey, Path> outlines;
    std::vector<VariationSetting> outlines_variations;

    GlyphRasterizer& rasterizer(std::size_t font) {
        if (rasterizers.size() <= font) rasterizers.resize(font + 1);
        if (!rasterizers[font])
            rasterizers[font] = std::make_unique<GlyphRasterizer>(renderer.fonts().font(font));
        return *rasterizers[font];
    }
};

class FontCore;

// A worker leased from a FontCore's pool for one call, returned when the lease ends.
class Lease {
public:
    Lease(FontCore& core, std::unique_ptr<Worker> worker) : core_(core), worker_(std::move(worker)) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease();
    Worker& operator*() { return *worker_; }
    Worker* operator->() { return worker_.get(); }

private:
    FontCore& core_;
    std::unique_ptr<Worker> worker_;
};

class FontCore {
public:
    // `sources`: (path str or bytes, face index, [(tag, value), ...]) for the font and then each
    // fallback font, in order.
    FontCore(const py::list& sources, bool system_fonts) : system_fonts_(system_fonts) {
        if (py::len(sources) == 0) throw py::value_error("fonts: the list is empty");
        if (py::len(sources) > kMaxCollectionFonts)
            throw py::value_error("fonts: " + std::to_string(py::len(sources)) +
                                  " fonts; at most " + std::to_string(kMaxCollectionFonts));
        struct Pending {
            std::string file;
            std::shared_ptr<const std::vector<std::uint8_t>> bytes;
            int face_index = 0;
            std::vector<VariationSetting> variations;
        };
        std::vector<Pending> pending;
        for (const py::handle item : sources) {
            if (!py::isinstance<py::tuple>(item) || py::len(item) != 3)
                throw py::type_error("fonts: expected (source, face_index, variations) tuples");
            auto t = py::reinterpret_borrow<py::tuple>(item);
            Pending p;
            if (PyBytes_Check(t[0].ptr())) {
                const std::string copy = t[0].cast<std::string>();
                p.bytes = std::make_shared<const std::vector<std::uint8_t>>(copy.begin(),
                                                                            copy.end());
            } else if (PyUnicode_Check(t[0].ptr())) {
                p.file = t[0].cast<std::string>();
            } else {
                throw py::type_error("font: expected a path (str) or the font's bytes");
            }
            const long long face = t[1].cast<long long>();
            if (face < 0 || face > kMaxFaceIndex)
                throw py::value_error("face_index: " + std::to_string(face) + " is outside 0.." +
                                      std::to_string(kMaxFaceIndex));
            p.face_index = static_cast<int>(face);
            for (const py::handle v : py::reinterpret_borrow<py::iterable>(t[2])) {
                if (!py::isinstance<py::tuple>(v) || py::len(v) != 2)
                    throw py::type_error("variations: expected (tag, value) pairs");
                auto pair = py::reinterpret_borrow<py::tuple>(v);
                p.variations.push_back({pair[0].cast<std::string>(), pair[1].cast<double>()});
            }
            pending.push_back(std::move(p));
        }
        std::unique_ptr<Worker> first;
        {
            py::gil_scoped_release release;
            for (Pending& p : pending) {
                FontFace face = p.bytes ? take(FontFace::from_memory(
                                              p.bytes, FontMemoryOptions{p.face_index, "<bytes>"}))
                                        : take(FontFace::open(p.file, p.face_index));
                sources_.push_back({std::move(face), std::move(p.variations)});
            }
            // The first worker checks what only a whole list can (variations against the axes,
            // a bitmap-only font without colour), and is kept for the first call.
            first = make_worker();
            FontCollection& fonts = first->renderer.fonts();
            for (std::size_t i = 0; i < fonts.size(); ++i)
                if (!fonts.font(i).has_color_bitmaps()) check(fonts.font(i).require_outlines());
        }
        idle_.push_back(std::move(first));
    }

    Lease lease() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!idle_.empty()) {
                std::unique_ptr<Worker> w = std::move(idle_.back());
                idle_.pop_back();
                return Lease(*this, std::move(w));
            }
        }
        return Lease(*this, make_worker());
    }

    void give_back(std::unique_ptr<Worker> worker) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (idle_.size() < kMaxIdleWorkers) idle_.push_back(std::move(worker));
    }

    py::dict info() {
        Lease w = leased();
        FontCollection& fonts = w->renderer.fonts();
        Font& font = fonts.font(0);
        const FontMetrics metrics = font.metrics();
        py::dict d;
        d["file"] = sources_[0].face.from_file() ? py::object(py::str(font.file())) : py::none();
        d["family"] = font.family_name();
        d["style"] = font.style_name();
        d["face_index"] = font.face_index();
        d["face_count"] = font.face_count();
        d["glyph_count"] = font.glyph_count();
        d["units_per_em"] = metrics.units_per_em;
        d["ascender"] = metrics.ascender;
        d["descender"] = metrics.descender;
        d["line_gap"] = metrics.line_gap;
        d["has_color"] = font.has_color_bitmaps();
        d["is_scalable"] = font.is_scalable();
        py::list axes;
        for (const VariationAxis& a : font.axes())
            axes.append(py::make_tuple(a.tag, a.name, a.min_value, a.default_value, a.max_value));
        d["axes"] = axes;
        py::list names;
        for (std::size_t i = 0; i < fonts.size(); ++i) names.append(fonts.source(i).file);
        d["fonts"] = names;
        return d;
    }

    py::array render(const py::object& text, const py::dict& options, const std::string& mode_name,
                     double default_size, const std::string& default_hinting) {
        const std::string utf8 = utf8_text(text, "text");
        RenderRequest req = render_request(options, default_size, hinting_named(default_hinting));
        const Mode mode = mode_named(mode_name);
        const TextRenderOptions& o = req.options;
        const bool gray_colours =
            o.format == CoverageFormat::Gray && opaque_gray(o.foreground) && opaque_gray(o.background);
        if (mode == Mode::Gray && !gray_colours)
            throw py::value_error("mode='gray' needs an opaque gray foreground and background and "
                                  "no lcd (use mode='rgba' or 'auto')");
        Lease w = leased();
        std::optional<Mask> mask;
        std::optional<Image> image;
        Status status = ok_status();
        {
            py::gil_scoped_release release;
            TextRenderer& r = w->renderer;
            if (mode == Mode::Gray || (mode == Mode::Auto && gray_colours)) {
                auto page = r.render_gray(utf8, o);
                if (page) {
                    mask = std::move(*page);
                } else if (mode == Mode::Auto && r.last_text_has_color()) {
                    // A gray page cannot show colour glyphs: such text gets an RGBA page.
                    auto rgba = r.render(utf8, o);
                    if (rgba) image = std::move(*rgba); else status = rgba.error();
                } else {
                    status = page.error();
                }
            } else {
                auto rgba = r.render(utf8, o);
                if (rgba) image = std::move(*rgba); else status = rgba.error();
            }
        }
        check(status);
        report(*w, req.strict);
        if (mask) {
            const py::ssize_t h = mask->height(), wd = mask->width();
            return adopt(std::move(*mask), {h, wd});
        }
        const py::ssize_t h = image->height(), wd = image->width();
        return adopt(std::move(*image), {h, wd, 4});
    }

    // (Path, page width, page height, first baseline y): every glyph's outline placed as render()
    // places it, in page pixels.
    py::tuple text_path(const py::object& text, const py::dict& options, double default_size,
                        const std::string& default_hinting) {
        const std::string utf8 = utf8_text(text, "text");
        RenderRequest req = render_request(options, default_size, hinting_named(default_hinting));
        const TextRenderOptions& o = req.options;
        if (o.shape.bold != 0)
            throw py::value_error("bold: text_path holds the fonts' own outlines; synthetic bold "
                                  "dilates the ink while it is rasterized and has no outline");
        Lease w = leased();
        PathObject out;
        TextLayout layout;
        Status status = ok_status();
        {
            py::gil_scoped_release release;
            status = lay_out_path(*w, utf8, o, out.path, layout);
        }
        check(status);
        report(*w, req.strict);
        const double width = std::max(1.0, std::ceil(layout.width_px));
        const double height = std::max(1.0, std::ceil(layout.height_px));
        const bool vertical = o.shape.direction == Direction::TopToBottom ||
                              o.shape.direction == Direction::BottomToTop;
        py::object baseline = py::none();
        if (!layout.lines.empty())
            baseline = py::float_(vertical ? layout.lines[0].baseline_x_px
                                           : layout.lines[0].baseline_y_px);
        return py::make_tuple(std::move(out), static_cast<long long>(width),
                              static_cast<long long>(height), baseline);
    }

    // (image, left, top, advance, gid, font index, drawn in colour) of one glyph: `key` a code
    // point (by_char) drawn by the font of the list that has it, or a glyph id of the first font.
    py::tuple glyph(long long key, bool by_char, const py::dict& options, const std::string& mode_name,
                    double default_size, const std::string& default_hinting) {
        GlyphRenderOptions g;
        g.size_px = option<double>(options, "size", default_size);
        g.hinting = hinting_named(option<std::string>(options, "hinting", default_hinting));
        g.slant = option<double>(options, "slant", 0.0);
        g.bold = option<double>(options, "bold", 0.0);
        g.offset_px = {option<double>(options, "offset_x", 0.0),
                       option<double>(options, "offset_y", 0.0)};
        g.color = color_options(options);
        g.color.foreground = colour(options, "foreground", g.color.foreground);
        const bool strict = option<bool>(options, "strict", false);
        const Mode mode = mode_named(mode_name);
        check_key(key, by_char);
        Lease w = leased();
        std::vector<std::uint8_t> pixels;
        PreparedGlyph prepared;
        std::size_t font = 0;
        bool missing = false;
        Status status = ok_status();
        {
            py::gil_scoped_release release;
            status = pick_glyph(*w, key, by_char, font, prepared.gid, missing);
            if (status) {
                GlyphRasterizer& r = w->rasterizer(font);
                auto made = r.prepare(prepared.gid, g);
                if (made) prepared = std::move(*made); else status = made.error();
            }
            if (status) status = draw_glyph(w->rasterizer(font), prepared, mode, pixels);
        }
        check(status);
        if (missing) missing_glyph(*w, static_cast<char32_t>(key), strict);
        const GlyphBox& box = prepared.box;
        const bool rgba = mode == Mode::Rgba || (mode == Mode::Auto && box.color);
        std::vector<py::ssize_t> shape{box.height, box.width};
        if (rgba) shape.push_back(4);
        return py::make_tuple(adopt_pixels(std::move(pixels), shape), box.left, box.top,
                              box.advance_px, prepared.gid, font, box.color);
    }

    // (Path, gid, font index, advance): a glyph's outline in pixels at `size`, y down, pen at
    // the origin.
    py::tuple outline(long long key, bool by_char, double size, const std::string& hinting) {
        check_key(key, by_char);
        const OutlineOptions options{size, hinting_named(hinting)};
        Lease w = leased();
        PathObject path;
        GlyphId gid = 0;
        std::size_t font = 0;
        bool missing = false;
        double advance = 0;
        Status status = ok_status();
        {
            py::gil_scoped_release release;
            status = pick_glyph(*w, key, by_char, font, gid, missing);
            if (status) {
                auto outline = w->renderer.fonts().font(font).outline(gid, options);
                if (outline) {
                    path.path = std::move(outline->path);
                    advance = outline->metrics.advance_px;
                } else {
                    status = outline.error();
                }
            }
        }
        check(status);
        if (missing) missing_glyph(*w, static_cast<char32_t>(key), false);
        return py::make_tuple(std::move(path), gid, font, advance);
    }

private:
    std::unique_ptr<Worker> make_worker() {
        auto fonts = take(FontCollection::from_face(sources_[0].face, sources_[0].variations));
        for (std::size_t i = 1; i < sources_.size(); ++i)
            take(fonts.add(sources_[i].face, sources_[i].variations));
        if (system_fonts_) fonts.set_fallback(system_fallback(fonts.font(0).family_name()));
        return std::make_unique<Worker>(
            Worker{take(TextRenderer::open(std::move(fonts))), {}, 0, {}, {}});
    }

    // A lease made with the GIL released (making a worker opens FreeType and HarfBuzz objects).
    Lease leased() {
        py::gil_scoped_release release;
        return lease();
    }

    static void check_key(long long key, bool by_char) {
        if (by_char) {
            if (key < 0 || key > 0x10FFFF || (key >= 0xD800 && key <= 0xDFFF))
                throw py::value_error("character: " + std::to_string(key) +
                                      " is not a Unicode scalar value");
        } else if (key < 0 || key > 0xFFFFFFFFLL) {
            throw py::value_error("glyph id: " + std::to_string(key) + " is negative or too large");
        }
    }

    // The font and glyph that draw `key`: the first font of the list that covers the character
    // (the system fallback's when enabled), else the first font's .notdef (missing = true).
    static Status pick_glyph(Worker& w, long long key, bool by_char, std::size_t& font,
                             GlyphId& gid, bool& missing) {
        font = 0;
        missing = false;
        if (!by_char) {
            gid = static_cast<GlyphId>(key);
            return ok_status();
        }
        FontCollection& fonts = w.renderer.fonts();
        const std::u32string cluster(1, static_cast<char32_t>(key));
        if (auto i = fonts.font_for(cluster)) {
            font = *i;
            gid = fonts.font(font).glyph_for_char(static_cast<char32_t>(key)).value_or(0);
        } else {
            gid = 0;
        }
        missing = gid == 0;
        return ok_status();
    }

    static Status draw_glyph(GlyphRasterizer& r, const PreparedGlyph& g, Mode mode,
                             std::vector<std::uint8_t>& pixels) {
        const GlyphBox& box = g.box;
        const bool rgba = mode == Mode::Rgba || (mode == Mode::Auto && box.color);
        const std::size_t w = static_cast<std::size_t>(box.width);
        const std::size_t h = static_cast<std::size_t>(box.height);
        pixels.assign(w * h * (rgba ? 4 : 1), 0);
        if (w == 0 || h == 0) return ok_status();
        if (!rgba) return r.draw(g, MaskView{pixels.data(), box.width, box.height,
                                             static_cast<std::ptrdiff_t>(w)});
        const RgbaView view{pixels.data(), box.width, box.height, static_cast<std::ptrdiff_t>(4 * w)};
        if (Status s = r.draw_rgba(g, view); !s) return s;
        // draw_rgba writes premultiplied RGBA; numpy and Pillow's "RGBA" are straight alpha.
        for (std::size_t i = 0; i < w * h; ++i) {
            std::uint8_t* p = pixels.data() + 4 * i;
            store_pixel(PixelFormat::Rgba8, p, load_pixel(PixelFormat::Rgba8Premultiplied, p));
        }
        return ok_status();
    }

    static Status lay_out_path(Worker& w, const std::string& utf8, const TextRenderOptions& o,
                               Path& out, TextLayout& layout) {
        FontCollection& fonts = w.renderer.fonts();
        // The first font's coordinates as TextRenderer sets them (its own, then the options').
        std::vector<VariationSetting> first;
        fonts.variations_for(0, o.shape.variations, first);
        if (Status s = fonts.font(0).set_variations(first); !s) return s;
        auto made = w.renderer.layout(utf8, o);
        if (!made) return made.error();
        layout = std::move(*made);
        // Each glyph's outline is loaded once (per renderer, while the variations stay) and
        // placed at every pen that uses it.
        const std::vector<VariationSetting>& variations = o.shape.variations;
        const auto same = [](const VariationSetting& a, const VariationSetting& b) {
            return a.tag == b.tag && a.value == b.value;
        };
        if (!std::equal(variations.begin(), variations.end(), w.outlines_variations.begin(),
                        w.outlines_variations.end(), same)) {
            w.outlines.clear();
            w.outlines_variations = variations;
        }
        const OutlineOptions outline_options{o.shape.size_px, o.hinting};
        const bool whole_pixel_pen = hints_horizontally(o.hinting);
        for (const PlacedGlyph& g : layout.glyphs) {
            const Worker::OutlineKey key{g.font, g.gid, o.shape.size_px, o.hinting, o.slant};
            auto found = w.outlines.find(key);
            if (found == w.outlines.end()) {
                auto outline = fonts.font(g.font).outline(g.gid, outline_options);
                if (!outline) return outline.error();
                // The synthetic slant, as GlyphRasterizer applies it (glyph.hpp).
                if (o.slant != 0) outline->path.transform(Affine::skew(-o.slant, 0));
                if (w.outlines.size() >= kMaxCachedOutlines) w.outlines.clear();
                found = w.outlines.emplace(key, std::move(outline->path)).first;
            }
            // Pens as TextRenderer places them for the hinting mode (text_renderer.hpp).
            const double x = whole_pixel_pen ? std::floor(g.x_px + 0.5) : g.x_px;
            append_path(out, found->second, Affine::translate({x, g.y_px}));
        }
        return ok_status();
    }

    // Missing glyphs, fallback warnings and SVG glyphs of the worker's last call: warnings, or
    // with `strict` a missing glyph is an Error. Needs the GIL.
    void report(Worker& w, bool strict) {
        TextRenderer& r = w.renderer;
        const std::vector<std::string>& warnings = r.fonts().warnings();
        for (; w.warnings_reported < warnings.size(); ++w.warnings_reported)
            warn(PyExc_UserWarning, warnings[w.warnings_reported]);
        if (const std::size_t svg = r.last_text_svg_glyphs(); svg > 0)
            warn(PyExc_UserWarning, std::to_string(svg) +
                                        (svg == 1 ? " glyph is an SVG colour glyph"
                                                  : " glyphs are SVG colour glyphs") +
                                        ", which bezel does not paint: drawn from the outline");
        const MissingGlyphs& missing = r.missing_glyphs();
        if (missing.count == 0) return;
        std::string what = font_names(r.fonts()) + ": no glyph for " +
                           describe_character(missing.first_code_point);
        if (missing.count > 1)
            what += " (and " + std::to_string(missing.count - 1) + " more " +
                    (missing.count == 2 ? "character" : "characters") + ")";
        if (strict) throw Failure(what + " (strict)");
        warn(missing_glyph_warning(), what + "; drawn as .notdef");
    }

    void missing_glyph(Worker& w, char32_t cp, bool strict) {
        const std::string what =
            font_names(w.renderer.fonts()) + ": no glyph for " + describe_character(cp);
        if (strict) throw Failure(what + " (strict)");
        warn(missing_glyph_warning(), what + "; drawn as .notdef");
    }

    std::vector<Source> sources_;
    bool system_fonts_ = false;
    std::mutex mutex_;
    std::vector<std::unique_ptr<Worker>> idle_;
};

Lease::~Lease() {
    if (worker_) core_.give_back(std::move(worker_));
}

}  // namespace

void bind_font(py::module_& m) {
    py::class_<FontCore>(m, "FontCore")
        .def(py::init<const py::list&, bool>(), py::arg("sources"), py::arg("system_fonts"))
        .def("info", &FontCore::info)
        .def("render", &FontCore::render, py::arg("text"), py::arg("options"), py::arg("mode"),
             py::arg("default_size"), py::arg("default_hinting"))
        .def("text_path", &FontCore::text_path, py::arg("text"), py::arg("options"),
             py::arg("default_size"), py::arg("default_hinting"))
        .def("glyph", &FontCore::glyph, py::arg("key"), py::arg("by_char"), py::arg("options"),
             py::arg("mode"), py::arg("default_size"), py::arg("default_hinting"))
        .def("outline", &FontCore::outline, py::arg("key"), py::arg("by_char"), py::arg("size"),
             py::arg("hinting"));
}

}  // namespace bezel::python
