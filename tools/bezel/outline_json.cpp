// The JSON form of `bezel outline`: the same data as the text form, numbers as doubles
// (pixels, y down, each glyph's pen at (0, 0); face metrics in font units, y up).
//
// {
//   "font": {"file", "family", "style", "face_index", "outlines": "quadratic"|"cubic",
//            "units_per_em", "ascender", "descender", "line_gap",        // font units, y up
//            "variations": [{"tag", "value"}]},
//   "size": px, "hinting": "none"|"light"|"full"|"auto",
//   "ascender_px", "descender_px": numbers (y up, as in the font),
//   "glyphs": [{
//     "gid": int, "name": string, "char": string (one character) or null, "code_point":
//     "U+XXXX" or null, "pen_x": px along the line, "advance": px,
//     "bounds": [x0, y0, x1, y1] (control box) or null for a blank glyph,
//     "contours": [{
//       "direction": "clockwise"|"counter-clockwise"|"degenerate"   (on screen, y down),
//       "signed_area": px² of the point polygon, y down (> 0 clockwise),
//       "first_point": index of the contour's first point in the glyph's point list,
//       "points": [{"x", "y", "kind": "on"|"off-conic"|"off-cubic"}],
//       "segments": [{"kind": "line"|"quad"|"cubic", "points": [[x, y], ...]}]  // 2, 3 or 4
//     }]
//   }]
// }
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "outline_model.hpp"

namespace bezel::cli {
namespace {

using nlohmann::json;

json glyph_json(const GlyphReport& g) {
    const GlyphOutline& o = g.outline;
    json glyph = {{"gid", g.gid}, {"name", g.name}};
    if (g.code_point) {
        std::string utf8;
        append_utf8(utf8, *g.code_point);
        glyph["char"] = utf8;
        glyph["code_point"] = format_code_point(*g.code_point);
    } else {
        glyph["char"] = nullptr;
        glyph["code_point"] = nullptr;
    }
    glyph["pen_x"] = g.pen_x_px;
    glyph["advance"] = o.metrics.advance_px;
    const Rect& b = o.metrics.bounds_px;
    glyph["bounds"] = b.is_empty() ? json(nullptr) : json::array({b.x0, b.y0, b.x1, b.y1});

    json contours = json::array();
    for (const Contour& c : g.contours) {
        json points = json::array();
        for (std::size_t i = c.first; i <= c.last; ++i)
            points.push_back({{"x", o.points[i].pos.x},
                              {"y", o.points[i].pos.y},
                              {"kind", point_kind_name(o.points[i].kind)}});
        json segments = json::array();
        for (const Segment& s : c.segments) {
            json sp = json::array();
            for (std::size_t i = 0; i < s.point_count(); ++i) sp.push_back({s.p[i].x, s.p[i].y});
            segments.push_back({{"kind", segment_kind_name(s.kind)}, {"points", sp}});
        }
        contours.push_back({{"direction", direction_name(c.direction)},
                            {"signed_area", c.signed_area_px2},
                            {"first_point", c.first},
                            {"points", points},
                            {"segments", segments}});
    }
    glyph["contours"] = contours;
    return glyph;
}

}  // namespace

std::string format_json(const OutlineReport& r) {
    json variations = json::array();
    for (const auto& v : r.variations) variations.push_back({{"tag", v.tag}, {"value", v.value}});
    json doc = {
        {"font",
         {{"file", r.font_file},
          {"family", r.family},
          {"style", r.style},
          {"face_index", r.face_index},
          {"outlines", r.cubic ? "cubic" : "quadratic"},
          {"units_per_em", r.metrics.units_per_em},
          {"ascender", r.metrics.ascender},
          {"descender", r.metrics.descender},
          {"line_gap", r.metrics.line_gap},
          {"variations", variations}}},
        {"size", r.size_px},
        {"hinting", hinting_name(r.hinting)},
        {"ascender_px", r.ascender_px()},
        {"descender_px", r.descender_px()},
    };
    json glyphs = json::array();
    for (const GlyphReport& g : r.glyphs) glyphs.push_back(glyph_json(g));
    doc["glyphs"] = glyphs;
    // Invalid UTF-8 in names from the font becomes U+FFFD instead of an exception.
    return doc.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace bezel::cli
