// Shaper: HarfBuzz shaping of one font file.
//
// Scale: HarfBuzz positions are integers in the units of hb_font_set_scale. bezel sets the scale
// to kUnitsPerPx units per pixel (s = round(size_px · 1024)), so advances and offsets keep 1/1024
// px of precision, and converts back with size_px / s (exact when size_px·1024 is an integer;
// otherwise it also undoes the rounding of s). At the largest size (16384 px) s = 2^24 and a
// glyph several em wide still fits HarfBuzz's 32-bit positions. No ppem is set: outlines are
// unhinted, and so are advances.
//
// Vertical runs (TopToBottom, BottomToTop): hb_font_create's font functions are HarfBuzz's own
// OpenType ones, which give vertical advances (vmtx; without it the font's ascender − descender)
// and vertical origins (horizontally half the glyph's advance; vertically VORG, else vmtx's top
// side bearing above the glyph's top, else HarfBuzz's fallback). HarfBuzz's offsets then lead
// from the vertical pen to the glyph's horizontal origin, where its outline is drawn:
// origin = pen + offset, in bezel's y down as for horizontal runs. Its y advances are negative
// (y up, the pen goes down) for both vertical directions (BottomToTop reverses the glyph order
// instead); negated, they are positive.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <hb-ot.h>
#include <hb.h>

#include "bezel/shape.hpp"
#include "text/shape_tags.hpp"
#include "text/utf8_decode.hpp"

namespace bezel {

using text_detail::parse_language_tag;
using text_detail::parse_script_tag;
using text_detail::tag_string;

namespace {

constexpr double kUnitsPerPx = 1024.0;

std::string format_number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The HarfBuzz face of a FontFace, made once and shared by every Shaper of the face (HarfBuzz
// faces are immutable once made and safe to read from any number of threads; each Shaper has its
// own hb_font). The blob reads the face's bytes in place; it needs no owner of its own, since the
// FontFace keeps the bytes alive for as long as it keeps this face. Null when HarfBuzz does not
// read the bytes as OpenType (a format only FreeType reads: Type 1, BDF, PCF).
std::shared_ptr<const void> make_hb_face(const FontFace& source) {
    hb_blob_t* blob = hb_blob_create(reinterpret_cast<const char*>(source.data()),
                                     static_cast<unsigned>(source.size()),
                                     HB_MEMORY_MODE_READONLY, nullptr, nullptr);
    const unsigned count = hb_face_count(blob);
    if (count == 0 || static_cast<unsigned>(source.face_index()) >= count) {
        hb_blob_destroy(blob);
        return nullptr;
    }
    hb_face_t* face = hb_face_create(blob, static_cast<unsigned>(source.face_index()));
    hb_blob_destroy(blob);   // the face holds its own reference
    hb_face_make_immutable(face);
    return std::shared_ptr<const void>(
        face, [](const void* f) { hb_face_destroy(static_cast<hb_face_t*>(const_cast<void*>(f))); });
}

hb_direction_t to_hb(Direction d) {
    switch (d) {
        case Direction::LeftToRight: return HB_DIRECTION_LTR;
        case Direction::RightToLeft: return HB_DIRECTION_RTL;
        case Direction::TopToBottom: return HB_DIRECTION_TTB;
        case Direction::BottomToTop: return HB_DIRECTION_BTT;
        case Direction::Auto: break;
    }
    return HB_DIRECTION_INVALID;
}

Direction from_hb(hb_direction_t d) {
    switch (d) {
        case HB_DIRECTION_RTL: return Direction::RightToLeft;
        case HB_DIRECTION_TTB: return Direction::TopToBottom;
        case HB_DIRECTION_BTT: return Direction::BottomToTop;
        default: return Direction::LeftToRight;
    }
}

}  // namespace

struct Shaper::Impl {
    std::string file;
    FontFace source;                          // keeps the bytes (and the shared face) alive
    std::shared_ptr<const void> face_owner;   // the face's shared HarfBuzz face
    hb_face_t* face = nullptr;                // face_owner's
    hb_font_t* font = nullptr;
    hb_buffer_t* buffer = nullptr;   // reused by every shape() call
    std::vector<hb_ot_var_axis_info_t> axes;
    int scale = 0;                   // the current hb_font_set_scale
    std::vector<hb_variation_t> applied;   // the variations the font has now
    std::vector<hb_variation_t> wanted;    // scratch
    std::vector<hb_feature_t> features;    // scratch

    explicit Impl(FontFace f) : source(std::move(f)) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl() {
        hb_buffer_destroy(buffer);
        hb_font_destroy(font);
    }

    Status set_variations(const std::vector<VariationSetting>& settings);
    // Checks options.size_px, applies the size and the variations; returns pixels per HarfBuzz
    // position unit.
    Expected<double> configure(const ShapeOptions& options);
};

Expected<double> Shaper::Impl::configure(const ShapeOptions& options) {
    if (!(options.size_px > 0 && options.size_px <= kMaxFontSizePx))
        return Error{"font size " + format_number(options.size_px) + " px: out of range (0, " +
                     format_number(kMaxFontSizePx) + "]"};
    if (auto ok = set_variations(options.variations); !ok) return ok.error();
    // At least one unit: a size below 1/2048 px would round the scale to 0 and divide by it
    // (fuzz_text). Such a text is far below a pixel either way; its positions stay finite.
    const int s = std::max(1, static_cast<int>(std::lround(options.size_px * kUnitsPerPx)));
    if (s != scale) {
        hb_font_set_scale(font, s, s);
        scale = s;
    }
    return options.size_px / s;
}

Status Shaper::Impl::set_variations(const std::vector<VariationSetting>& settings) {
    wanted.clear();
    for (const VariationSetting& s : settings) {
        const hb_ot_var_axis_info_t* axis = nullptr;
        for (const auto& a : axes)
            if (tag_string(a.tag) == s.tag) axis = &a;
        if (axis == nullptr) {
            if (axes.empty())
                return Error{file + ": variation axis '" + s.tag +
                             "': the font has no variation axes"};
            return Error{file + ": unknown variation axis '" + s.tag + "'"};
        }
        if (!(s.value >= axis->min_value && s.value <= axis->max_value))  // also rejects NaN
            return Error{file + ": variation " + s.tag + "=" + format_number(s.value) +
                         " out of range [" + format_number(axis->min_value) + ", " +
                         format_number(axis->max_value) + "]"};
        wanted.push_back({axis->tag, static_cast<float>(s.value)});
    }
    const bool same = wanted.size() == applied.size() &&
                      std::equal(wanted.begin(), wanted.end(), applied.begin(),
                                 [](const hb_variation_t& a, const hb_variation_t& b) {
                                     return a.tag == b.tag && a.value == b.value;
                                 });
    if (same) return ok_status();
    // Later settings of the same tag win, as in hb_font_set_variations.
    hb_font_set_variations(font, wanted.data(), static_cast<unsigned>(wanted.size()));
    applied = wanted;
    return ok_status();
}

Shaper::Shaper(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Shaper::Shaper(Shaper&&) noexcept = default;
Shaper& Shaper::operator=(Shaper&&) noexcept = default;
Shaper::~Shaper() = default;

Status check_script_tag(const std::string& tag) {
    auto script = parse_script_tag(tag);
    if (!script) return script.error();
    return ok_status();
}

Status check_language_tag(const std::string& tag) {
    auto language = parse_language_tag(tag);
    if (!language) return language.error();
    return ok_status();
}

Expected<Shaper> Shaper::open(const std::string& file, int face_index) {
    auto face = FontFace::open(file, face_index);
    if (!face) return face.error();
    return open(*face);
}

Expected<Shaper> Shaper::open(const FontFace& source) {
    auto impl = std::make_unique<Impl>(source);
    impl->file = source.name();
    impl->face_owner = font_detail::derived_state(source, make_hb_face);
    if (!impl->face_owner) return Error{impl->file + ": not an OpenType or TrueType font"};
    impl->face = static_cast<hb_face_t*>(const_cast<void*>(impl->face_owner.get()));
    if (hb_face_get_glyph_count(impl->face) == 0)
        return Error{impl->file + ": face " + std::to_string(source.face_index()) +
                     " has no glyphs"};
    impl->font = hb_font_create(impl->face);
    impl->buffer = hb_buffer_create();
    if (!hb_buffer_allocation_successful(impl->buffer))
        return Error{impl->file + ": cannot allocate a shaping buffer"};
    unsigned n_axes = hb_ot_var_get_axis_count(impl->face);
    impl->axes.resize(n_axes);
    hb_ot_var_get_axis_infos(impl->face, 0, &n_axes, impl->axes.data());
    impl->axes.resize(n_axes);
    return Shaper(std::move(impl));
}

Expected<ShapedRun> Shaper::shape(std::string_view utf8, const ShapeOptions& options) {
    Impl& im = *impl_;
    if (!(options.size_px > 0 && options.size_px <= kMaxFontSizePx))
        return Error{"font size " + format_number(options.size_px) + " px: out of range (0, " +
                     format_number(kMaxFontSizePx) + "]"};
    if (!(options.bold >= 0 && options.bold <= kMaxSyntheticBold))   // NaN fails too
        return Error{"bold " + format_number(options.bold) + ": out of range [0, " +
                     format_number(kMaxSyntheticBold) + "]"};
    if (utf8.size() > kMaxTextBytes)
        return Error{"text of " + std::to_string(utf8.size()) + " bytes: longer than the " +
                     std::to_string(kMaxTextBytes) + " allowed"};
    for (std::size_t i = 0; i < utf8.size();) {
        char32_t cp;
        const std::size_t n = text_detail::decode_one(utf8, i, cp);
        if (n == 0) return text_detail::invalid_utf8(i);
        i += n;
    }
    hb_script_t script = HB_SCRIPT_INVALID;
    if (!options.script.empty()) {
        auto s = parse_script_tag(options.script);
        if (!s) return s.error();
        script = *s;
    }
    hb_language_t language = nullptr;
    if (!options.language.empty()) {
        auto l = parse_language_tag(options.language);
        if (!l) return l.error();
        language = *l;
    }
    auto configured = im.configure(options);   // the size again, then the variations
    if (!configured) return configured.error();
    const double px_per_unit = *configured;

    im.features.clear();
    for (const FeatureSetting& f : options.features) {
        if (f.tag.empty() || f.tag.size() > 4)
            return Error{"feature '" + f.tag + "': the tag must have 1 to 4 characters"};
        hb_feature_t hf;
        hf.tag = hb_tag_from_string(f.tag.data(), static_cast<int>(f.tag.size()));
        hf.value = f.value;
        hf.start = f.start >= HB_FEATURE_GLOBAL_END ? HB_FEATURE_GLOBAL_END
                                                    : static_cast<unsigned>(f.start);
        hf.end = f.end >= HB_FEATURE_GLOBAL_END ? HB_FEATURE_GLOBAL_END
                                                : static_cast<unsigned>(f.end);
        im.features.push_back(hf);
    }

    hb_buffer_t* buf = im.buffer;
    hb_buffer_clear_contents(buf);
    hb_buffer_add_utf8(buf, utf8.data(), static_cast<int>(utf8.size()), 0,
                       static_cast<int>(utf8.size()));
    if (options.direction != Direction::Auto) hb_buffer_set_direction(buf, to_hb(options.direction));
    if (script != HB_SCRIPT_INVALID) hb_buffer_set_script(buf, script);
    if (language != nullptr) hb_buffer_set_language(buf, language);
    hb_buffer_guess_segment_properties(buf);
    hb_shape(im.font, buf, im.features.data(), static_cast<unsigned>(im.features.size()));
    if (!hb_buffer_allocation_successful(buf))
        return Error{im.file + ": out of memory while shaping " + std::to_string(utf8.size()) +
                     " bytes of text"};

    unsigned n = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
    ShapedRun run;
    const hb_direction_t dir = hb_buffer_get_direction(buf);
    run.direction = from_hb(dir);
    run.script = tag_string(hb_script_to_iso15924_tag(hb_buffer_get_script(buf)));
    run.glyphs.resize(n);
    // ShapeOptions::bold: a nonzero advance grows by bold · size_px, away from zero (a vertical
    // advance is negative in HarfBuzz's y-up frame and positive here, y down).
    const double bold_px = options.bold * options.size_px;
    auto widened = [bold_px](hb_position_t advance) {
        return advance > 0 ? bold_px : advance < 0 ? -bold_px : 0.0;
    };
    for (unsigned i = 0; i < n; ++i) {
        ShapedGlyph& g = run.glyphs[i];
        g.gid = info[i].codepoint;
        g.cluster = info[i].cluster;
        // HarfBuzz's y axis points up; bezel's down.
        g.x_advance_px = pos[i].x_advance * px_per_unit + widened(pos[i].x_advance);
        g.y_advance_px = -(pos[i].y_advance * px_per_unit + widened(pos[i].y_advance));
        g.x_offset_px = pos[i].x_offset * px_per_unit;
        g.y_offset_px = -pos[i].y_offset * px_per_unit;
        run.advance_px += HB_DIRECTION_IS_HORIZONTAL(dir) ? g.x_advance_px : g.y_advance_px;
    }
    return run;
}

Expected<FontExtents> Shaper::extents(const ShapeOptions& options) {
    auto px_per_unit = impl_->configure(options);
    if (!px_per_unit) return px_per_unit.error();
    const hb_direction_t dir = options.direction == Direction::Auto ? HB_DIRECTION_LTR
                                                                     : to_hb(options.direction);
    hb_font_extents_t e{};
    hb_font_get_extents_for_direction(impl_->font, dir, &e);
    return FontExtents{e.ascender * *px_per_unit, e.descender * *px_per_unit,
                       e.line_gap * *px_per_unit};
}

}  // namespace bezel
