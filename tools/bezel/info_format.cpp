// The text and JSON forms of `bezel info`.
//
// JSON (a stable contract; numbers as the font stores them, font units, y up):
// {
//   "file": string, "face_index": int, "face_count": int,
//   "family": string, "style": string, "postscript_name": string ("" when absent),
//   "version": string ("" when absent),
//   "glyph_count": int, "units_per_em": int,
//   "outline_format": "TrueType"|"CFF"|"CFF2"|"bitmap"|"none",
//   "ascender": number, "descender": number, "line_gap": number,
//   "axes": [{"tag", "name", "min", "default", "max"}],
//   "named_instances": [{"name": string, "coordinates": {"<tag>": number, ...}}],
//   "tables": [{"tag": string (4 characters), "length": int (bytes)}],
//   "scripts": [ISO 15924 tag, ...],
//   "color": {"formats": ["COLRv1"|"COLRv0"|"CBDT"|"sbix"|"SVG", ...],
//             "palettes": [{"entries": ["#rrggbbaa", ...], "light_background": bool,
//                           "dark_background": bool}]}
// }
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "info.hpp"

namespace bezel::cli {

namespace {

using nlohmann::ordered_json;

std::string coordinates_text(const NamedInstance& instance) {
    std::string s;
    for (const VariationSetting& c : instance.coordinates) {
        if (!s.empty()) s += ",";
        s += c.tag + "=" + plain_number(c.value);
    }
    return s;
}

void line(std::string& out, const char* key, const std::string& value) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%-13s", key);
    out += buf;
    out += value;
    out += '\n';
}

std::vector<std::string> color_format_names(const ColorTables& t) {
    std::vector<std::string> out;
    if (t.colr_v1) out.emplace_back("COLRv1");
    if (t.colr_v0) out.emplace_back("COLRv0");
    if (t.cbdt) out.emplace_back("CBDT");
    if (t.sbix) out.emplace_back("sbix");
    if (t.svg) out.emplace_back("SVG");
    return out;
}

std::string hex_colour(Rgba8 c) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x%02x", c.r, c.g, c.b, c.a);
    return buf;
}

}  // namespace

std::string format_info_text(const FontInfo& info) {
    std::string out;
    line(out, "file", info.file);
    line(out, "face", std::to_string(info.face_index) + " of " + std::to_string(info.face_count));
    line(out, "family", info.family);
    line(out, "style", info.style);
    if (!info.postscript_name.empty()) line(out, "postscript", info.postscript_name);
    if (!info.version.empty()) line(out, "version", info.version);
    line(out, "glyphs", std::to_string(info.glyph_count));
    line(out, "outlines", info.outline_format);
    line(out, "units/em", std::to_string(info.metrics.units_per_em));
    line(out, "ascender", plain_number(info.metrics.ascender));
    line(out, "descender", plain_number(info.metrics.descender));
    line(out, "line gap", plain_number(info.metrics.line_gap));
    for (const VariationAxis& a : info.axes)
        line(out, "axis", a.tag + " " + plain_number(a.min_value) + ".." + plain_number(a.default_value) +
                              ".." + plain_number(a.max_value) + " (" + a.name + ")");
    for (const NamedInstance& i : info.instances)
        line(out, "instance", i.name + " " + coordinates_text(i));
    std::string scripts;
    for (const std::string& s : info.scripts) scripts += (scripts.empty() ? "" : " ") + s;
    line(out, "scripts", scripts.empty() ? "(none of the probed scripts)" : scripts);
    std::string colour;
    for (const std::string& f : color_format_names(info.color)) colour += (colour.empty() ? "" : " ") + f;
    if (info.color.svg) colour += " (SVG glyphs are drawn from their outlines)";
    line(out, "colour", colour.empty() ? "none" : colour);
    for (std::size_t i = 0; i < info.palettes.size(); ++i) {
        const Palette& p = info.palettes[i];
        std::string entries;
        for (Rgba8 c : p.entries) entries += " " + hex_colour(c);
        if (p.for_light_background) entries += " (for light backgrounds)";
        if (p.for_dark_background) entries += " (for dark backgrounds)";
        line(out, "palette", std::to_string(i) + ":" + entries);
    }
    line(out, "tables", std::to_string(info.tables.size()));
    for (const FontTable& t : info.tables) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "  '%s' %10u bytes\n", t.tag.c_str(), t.length);
        out += buf;
    }
    return out;
}

std::string format_info_json(const FontInfo& info) {
    ordered_json j;
    j["file"] = info.file;
    j["face_index"] = info.face_index;
    j["face_count"] = info.face_count;
    j["family"] = info.family;
    j["style"] = info.style;
    j["postscript_name"] = info.postscript_name;
    j["version"] = info.version;
    j["glyph_count"] = info.glyph_count;
    j["units_per_em"] = info.metrics.units_per_em;
    j["outline_format"] = info.outline_format;
    j["ascender"] = info.metrics.ascender;
    j["descender"] = info.metrics.descender;
    j["line_gap"] = info.metrics.line_gap;
    j["axes"] = ordered_json::array();
    for (const VariationAxis& a : info.axes)
        j["axes"].push_back({{"tag", a.tag}, {"name", a.name}, {"min", a.min_value},
                             {"default", a.default_value}, {"max", a.max_value}});
    j["named_instances"] = ordered_json::array();
    for (const NamedInstance& i : info.instances) {
        ordered_json coords = ordered_json::object();
        for (const VariationSetting& c : i.coordinates) coords[c.tag] = c.value;
        j["named_instances"].push_back({{"name", i.name}, {"coordinates", coords}});
    }
    j["tables"] = ordered_json::array();
    for (const FontTable& t : info.tables)
        j["tables"].push_back({{"tag", t.tag}, {"length", t.length}});
    j["scripts"] = info.scripts;
    ordered_json palettes = ordered_json::array();
    for (const Palette& p : info.palettes) {
        ordered_json entries = ordered_json::array();
        for (Rgba8 c : p.entries) entries.push_back(hex_colour(c));
        palettes.push_back({{"entries", std::move(entries)},
                            {"light_background", p.for_light_background},
                            {"dark_background", p.for_dark_background}});
    }
    j["color"] = {{"formats", color_format_names(info.color)}, {"palettes", std::move(palettes)}};
    return j.dump(2) + "\n";
}

}  // namespace bezel::cli
