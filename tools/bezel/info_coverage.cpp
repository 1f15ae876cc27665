// `bezel info --coverage TEXT`: which characters of a text the font maps, as text or JSON.
#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "info.hpp"

namespace bezel::cli {

CoverageReport coverage_of(const Font& font, const std::u32string& text) {
    CoverageReport report;
    report.file = font.file();
    report.face_index = font.face_index();
    std::u32string seen;
    for (char32_t c : text) {
        if (seen.find(c) != std::u32string::npos) continue;
        seen.push_back(c);
        report.entries.push_back({c, font.glyph_for_char(c)});
    }
    return report;
}

Expected<CoverageReport> coverage_of(FontCollection& fonts, const std::string& utf8) {
    ShapeOptions shape;
    auto layout = layout_text(fonts, utf8, shape, LayoutOptions{});
    if (!layout) return layout.error();
    // The font of each cluster (its first byte); a character belongs to the cluster starting at
    // or before it.
    std::map<std::uint32_t, std::size_t> font_at;
    for (const PlacedGlyph& g : layout->glyphs) font_at.emplace(g.cluster, g.font);
    CoverageReport report;
    report.file = fonts.source(0).file;
    report.face_index = fonts.source(0).face_index;
    for (std::size_t i = 0; i < fonts.size(); ++i) report.fonts.push_back(fonts.source(i).file);
    auto text = decode_utf8(utf8);
    if (!text) return text.error();
    std::u32string seen;
    std::uint32_t offset = 0;
    for (char32_t c : *text) {
        std::string bytes;
        append_utf8(bytes, c);
        const std::uint32_t at = offset;
        offset += static_cast<std::uint32_t>(bytes.size());
        if (seen.find(c) != std::u32string::npos) continue;
        seen.push_back(c);
        auto it = font_at.upper_bound(at);
        const std::size_t font = it == font_at.begin() ? 0 : std::prev(it)->second;
        report.entries.push_back({c, fonts.font(font).glyph_for_char(c), font});
    }
    return report;
}

namespace {

std::size_t missing_count(const CoverageReport& report) {
    std::size_t n = 0;
    for (const CoverageReport::Entry& e : report.entries) n += !e.gid.has_value();
    return n;
}

// A character as it can be shown on a line: controls and spaces by their code point alone.
std::string printable(char32_t c) {
    if (c < 0x21 || (c >= 0x7f && c < 0xa1)) return "";
    std::string s;
    append_utf8(s, c);
    return s;
}

}  // namespace

std::string format_coverage_text(const CoverageReport& report) {
    const std::size_t total = report.entries.size(), missing = missing_count(report);
    std::string out = "file     " + report.file + " (face " + std::to_string(report.face_index) +
                      ")\ncovered  " + std::to_string(total - missing) + " of " +
                      std::to_string(total) + " characters\n";
    const bool listed = report.fonts.size() > 1;
    if (listed) {
        out += "fonts\n";
        for (std::size_t i = 0; i < report.fonts.size(); ++i)
            out += "  " + std::to_string(i) + "  " + report.fonts[i] + "\n";
    }
    for (const CoverageReport::Entry& e : report.entries) {
        char code[16];
        std::snprintf(code, sizeof code, "%-9s", format_code_point(e.code_point).c_str());
        out += "  " + std::string(code) + printable(e.code_point) + "  " +
               (e.gid ? "gid " + std::to_string(*e.gid) : std::string("missing")) +
               (listed && e.gid ? "  font " + std::to_string(e.font) : std::string()) + "\n";
    }
    return out;
}

std::string format_coverage_json(const CoverageReport& report) {
    nlohmann::ordered_json j;
    j["file"] = report.file;
    j["face_index"] = report.face_index;
    j["characters"] = report.entries.size();
    j["missing"] = missing_count(report);
    const bool listed = report.fonts.size() > 1;
    if (listed) j["fonts"] = report.fonts;
    j["coverage"] = nlohmann::ordered_json::array();
    for (const CoverageReport::Entry& e : report.entries) {
        std::string utf8;
        append_utf8(utf8, e.code_point);
        nlohmann::ordered_json entry = {{"char", utf8},
                                        {"code_point", format_code_point(e.code_point)}};
        entry["gid"] = e.gid ? nlohmann::ordered_json(*e.gid) : nlohmann::ordered_json(nullptr);
        if (listed)
            entry["font"] = e.gid ? nlohmann::ordered_json(e.font) : nlohmann::ordered_json(nullptr);
        j["coverage"].push_back(std::move(entry));
    }
    return j.dump(2) + "\n";
}

}  // namespace bezel::cli
