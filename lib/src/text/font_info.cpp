// font_info: what `bezel info` prints. FreeType (through Font) gives the names, metrics, glyph
// count and axes the rest of bezel uses; HarfBuzz reads the table directory, the PostScript
// name, the version string and the named instances (fvar), which Font does not expose.
#include <hb-ot.h>
#include <hb.h>

#include "bezel/font_info.hpp"
#include "text/shape_tags.hpp"

namespace bezel {

namespace {

// Representative letters per script: a script counts as covered when the cmap maps all of them.
// Two to five letters from different parts of each block (first, last, common ones), so a font
// with a partial block still counts but one with a stray letter or two does not.
struct ScriptProbe {
    const char* tag;
    char32_t letters[5];   // zero-terminated when shorter
};

constexpr ScriptProbe kScriptProbes[] = {
    {"Latn", {0x41, 0x5A, 0x61, 0x7A}},
    {"Grek", {0x391, 0x3A9, 0x3B1, 0x3C9}},
    {"Cyrl", {0x410, 0x42F, 0x430, 0x44F}},
    {"Armn", {0x531, 0x556, 0x561, 0x586}},
    {"Hebr", {0x5D0, 0x5D1, 0x5E9, 0x5EA}},
    {"Arab", {0x627, 0x628, 0x639, 0x64A, 0x647}},
    {"Syrc", {0x710, 0x712, 0x72C}},
    {"Thaa", {0x780, 0x785, 0x7A5}},
    {"Nkoo", {0x7CA, 0x7DE}},
    {"Deva", {0x905, 0x915, 0x939, 0x93F}},
    {"Beng", {0x985, 0x995, 0x9B9}},
    {"Guru", {0xA05, 0xA15, 0xA39}},
    {"Gujr", {0xA85, 0xA95, 0xAB9}},
    {"Orya", {0xB05, 0xB15, 0xB39}},
    {"Taml", {0xB85, 0xB95, 0xBB9}},
    {"Telu", {0xC05, 0xC15, 0xC39}},
    {"Knda", {0xC85, 0xC95, 0xCB9}},
    {"Mlym", {0xD05, 0xD15, 0xD39}},
    {"Sinh", {0xD85, 0xD9A, 0xDC4}},
    {"Thai", {0xE01, 0xE2E}},
    {"Laoo", {0xE81, 0xEAE}},
    {"Tibt", {0xF40, 0xF67}},
    {"Mymr", {0x1000, 0x1021}},
    {"Geor", {0x10D0, 0x10F0}},
    {"Ethi", {0x1200, 0x1350}},
    {"Cher", {0x13A0, 0x13F4}},
    {"Cans", {0x1401, 0x1676}},
    {"Ogam", {0x1681, 0x169A}},
    {"Runr", {0x16A0, 0x16DF}},
    {"Khmr", {0x1780, 0x17A2}},
    {"Mong", {0x1820, 0x1842}},
    {"Copt", {0x2C80, 0x2CB1}},
    {"Tfng", {0x2D30, 0x2D63}},
    {"Brai", {0x2801, 0x28FF}},
    {"Hira", {0x3042, 0x3093}},
    {"Kana", {0x30A2, 0x30F3}},
    {"Bopo", {0x3105, 0x3129}},
    {"Hani", {0x4E00, 0x4E2D, 0x9FA5}},
    {"Lisu", {0xA4D0, 0xA4FD}},
    {"Vaii", {0xA500, 0xA60B}},
    {"Hang", {0xAC00, 0xD7A3}},
};

std::string name_string(hb_face_t* face, hb_ot_name_id_t id) {
    static const hb_language_t english = hb_language_from_string("en", -1);
    unsigned size = hb_ot_name_get_utf8(face, id, english, nullptr, nullptr);
    if (size == 0) return {};
    std::string s(size + 1, '\0');
    unsigned len = size + 1;
    hb_ot_name_get_utf8(face, id, english, &len, s.data());
    s.resize(len);
    return s;
}

std::string outline_format(const std::vector<FontTable>& tables) {
    auto has = [&](const char* tag) {
        for (const FontTable& t : tables)
            if (t.tag == tag) return true;
        return false;
    };
    if (has("glyf")) return "TrueType";
    if (has("CFF ")) return "CFF";
    if (has("CFF2")) return "CFF2";
    if (has("CBDT") || has("EBDT") || has("sbix") || has("bdat")) return "bitmap";
    return "none";
}

}  // namespace

Expected<FontInfo> font_info(const std::string& file, int face_index) {
    auto font = Font::open(file, face_index);
    if (!font) return font.error();
    FontInfo info;
    info.file = file;
    info.face_index = face_index;
    info.face_count = font->face_count();
    info.family = font->family_name();
    info.style = font->style_name();
    info.glyph_count = font->glyph_count();
    info.metrics = font->metrics();
    info.axes = font->axes();
    info.color = color_tables(*font);
    info.palettes = palettes(*font);
    for (const ScriptProbe& probe : kScriptProbes) {
        bool covered = true;
        for (char32_t c : probe.letters)
            if (c != 0 && !font->glyph_for_char(c)) covered = false;
        if (covered) info.scripts.emplace_back(probe.tag);
    }

    hb_blob_t* blob = hb_blob_create_from_file_or_fail(file.c_str());
    if (blob == nullptr) return Error{file + ": cannot read the file"};
    hb_face_t* face = hb_face_create(blob, static_cast<unsigned>(face_index));
    hb_blob_destroy(blob);   // the face holds its own reference

    info.postscript_name = name_string(face, HB_OT_NAME_ID_POSTSCRIPT_NAME);
    info.version = name_string(face, HB_OT_NAME_ID_VERSION_STRING);
    hb_tag_t tags[64];
    for (unsigned start = 0;;) {
        unsigned count = 64;
        const unsigned total = hb_face_get_table_tags(face, start, &count, tags);
        for (unsigned i = 0; i < count; ++i) {
            hb_blob_t* table = hb_face_reference_table(face, tags[i]);
            info.tables.push_back({text_detail::tag_string(tags[i]), hb_blob_get_length(table)});
            hb_blob_destroy(table);
        }
        start += count;
        if (count == 0 || start >= total) break;
    }
    info.outline_format = outline_format(info.tables);

    const unsigned n_instances = hb_ot_var_get_named_instance_count(face);
    unsigned n_axes = hb_ot_var_get_axis_count(face);
    std::vector<hb_ot_var_axis_info_t> axes(n_axes);
    hb_ot_var_get_axis_infos(face, 0, &n_axes, axes.data());
    std::vector<float> coords(n_axes);
    for (unsigned i = 0; i < n_instances; ++i) {
        NamedInstance instance;
        instance.name = name_string(face, hb_ot_var_named_instance_get_subfamily_name_id(face, i));
        unsigned n = n_axes;
        hb_ot_var_named_instance_get_design_coords(face, i, &n, coords.data());
        for (unsigned a = 0; a < n && a < n_axes; ++a)
            instance.coordinates.push_back({text_detail::tag_string(axes[a].tag), coords[a]});
        info.instances.push_back(std::move(instance));
    }
    hb_face_destroy(face);
    return info;
}

}  // namespace bezel
