// FontFace: fonts from memory equal the same font from its file (outlines, shaping, glyph
// bitmaps), caller-owned and shared-owned bytes, bad bytes as errors naming the font, one face
// shared by Font and Shaper; a GlyphRasterizer outliving the Font it was made from; pixel
// metrics; Expected's loud failure on a missing value.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "bezel/text.hpp"

namespace bezel {
namespace {

const std::string kDejaVu = BEZEL_FONTS_DIR "/dejavu-sans/DejaVuSans.ttf";
const std::string kCantarell = BEZEL_FONTS_DIR "/cantarell/Cantarell-Regular.otf";
const std::string kEdgeTtc = BEZEL_FONTS_DIR "/edge-cases/EdgeCases.ttc";

std::vector<std::uint8_t> read_bytes(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every outline point of `text` at 23 px, hinted as asked, flattened into one list.
std::vector<OutlinePoint> outline_points(Font& font, const std::u32string& text, Hinting hinting) {
    std::vector<OutlinePoint> all;
    for (char32_t c : text) {
        auto outline = font.outline(font.glyph_for_char(c).value(), {23.0, hinting});
        EXPECT_TRUE(outline) << outline.error().message;
        if (outline) all.insert(all.end(), outline->points.begin(), outline->points.end());
    }
    return all;
}

void expect_same_points(const std::vector<OutlinePoint>& a, const std::vector<OutlinePoint>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].pos.x, b[i].pos.x) << "point " << i;   // exact: the same bytes, the same code
        EXPECT_EQ(a[i].pos.y, b[i].pos.y) << "point " << i;
        EXPECT_EQ(a[i].kind, b[i].kind) << "point " << i;
    }
}

void expect_same_shaping(Shaper& a, Shaper& b, const std::string& text) {
    ShapeOptions o;
    o.size_px = 19;
    auto ra = a.shape(text, o);
    auto rb = b.shape(text, o);
    ASSERT_TRUE(ra && rb);
    ASSERT_EQ(ra->glyphs.size(), rb->glyphs.size());
    for (std::size_t i = 0; i < ra->glyphs.size(); ++i) {
        EXPECT_EQ(ra->glyphs[i].gid, rb->glyphs[i].gid);
        EXPECT_EQ(ra->glyphs[i].x_advance_px, rb->glyphs[i].x_advance_px);
        EXPECT_EQ(ra->glyphs[i].x_offset_px, rb->glyphs[i].x_offset_px);
    }
}

TEST(FontFace, MemoryFontEqualsFileFontGlyphForGlyph) {
    for (const std::string& file : {kDejaVu, kCantarell}) {
        SCOPED_TRACE(file);
        const std::vector<std::uint8_t> bytes = read_bytes(file);
        auto face = FontFace::from_memory(bytes.data(), bytes.size(), {0, "embedded font"});
        ASSERT_TRUE(face) << face.error().message;
        EXPECT_FALSE(face->from_file());
        EXPECT_EQ(face->name(), "embedded font");
        EXPECT_EQ(face->data(), bytes.data());   // borrowed, not copied
        auto from_memory = Font::open(*face);
        auto from_file = Font::open(file);
        ASSERT_TRUE(from_memory && from_file);
        EXPECT_EQ(from_memory->file(), "embedded font");
        EXPECT_EQ(from_memory->glyph_count(), from_file->glyph_count());
        const std::u32string text = U"Hamburgefonstiv&@g";
        for (Hinting h : {Hinting::None, Hinting::Full}) {
            expect_same_points(outline_points(*from_memory, text, h),
                               outline_points(*from_file, text, h));
        }
        auto shaper_memory = Shaper::open(*face);
        auto shaper_file = Shaper::open(file);
        ASSERT_TRUE(shaper_memory && shaper_file);
        expect_same_shaping(*shaper_memory, *shaper_file, "Waffles, AVATAR; fi ffl");
    }
}

// A TextRenderer of a memory face draws the page the file's renderer draws, pixel for pixel,
// and a variation set on the list reaches it (FontCollection::from_face).
TEST(FontFace, TextRendererOfAMemoryFaceDrawsTheFilesPage) {
    auto bytes = std::make_shared<const std::vector<std::uint8_t>>(read_bytes(kDejaVu));
    auto face = FontFace::from_memory(bytes, {0, "embedded"});
    ASSERT_TRUE(face) << face.error().message;
    auto from_memory = TextRenderer::open(*face);
    auto from_file = TextRenderer::open(kDejaVu);
    ASSERT_TRUE(from_memory && from_file);
    EXPECT_EQ(from_memory->font().file(), "embedded");
    TextRenderOptions o;
    o.shape.size_px = 17;
    auto a = from_memory->render("Hamburgefonstiv AV 0.5", o);
    auto b = from_file->render("Hamburgefonstiv AV 0.5", o);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(*a, *b);
    // A variation the font does not have is FontCollection::add's error, naming the face.
    auto varied = FontCollection::from_face(*face, {{"wght", 700}});
    ASSERT_FALSE(varied);
    EXPECT_NE(varied.error().message.find("embedded"), std::string::npos) << varied.error().message;
}

TEST(FontFace, SharedBytesLiveAsLongAsTheLastUser) {
    auto bytes = std::make_shared<const std::vector<std::uint8_t>>(read_bytes(kDejaVu));
    std::weak_ptr<const std::vector<std::uint8_t>> watch = bytes;
    std::optional<Font> font;
    std::optional<Shaper> shaper;
    {
        auto face = FontFace::from_memory(std::move(bytes), {0, "shared"});
        ASSERT_TRUE(face) << face.error().message;
        font.emplace(std::move(Font::open(*face).value()));
        shaper.emplace(std::move(Shaper::open(*face).value()));
    }
    // The caller's pointer and the face are gone; the Font and the Shaper hold the bytes.
    EXPECT_FALSE(watch.expired());
    auto outline = font->outline(font->glyph_for_char(U'g').value(), {});
    ASSERT_TRUE(outline) << outline.error().message;
    EXPECT_FALSE(outline->path.empty());
    auto run = shaper->shape("go", {});
    ASSERT_TRUE(run);
    EXPECT_EQ(run->glyphs.size(), 2u);
    font.reset();
    EXPECT_FALSE(watch.expired());   // the Shaper still holds them
    shaper.reset();
    EXPECT_TRUE(watch.expired());
}

TEST(FontFace, FontAndShaperOfOneFaceShareItsBytes) {
    auto face = FontFace::open(kDejaVu);
    ASSERT_TRUE(face) << face.error().message;
    EXPECT_TRUE(face->from_file());
    auto font = Font::open(*face);
    ASSERT_TRUE(font);
    EXPECT_EQ(font->face().id(), face->id());
    EXPECT_EQ(font->face().data(), face->data());
    auto again = FontFace::open(kDejaVu);
    ASSERT_TRUE(again);
    EXPECT_NE(again->id(), face->id());   // opened separately: another face
    // A collection opens one face per font and makes its Font and Shaper from it.
    auto fonts = FontCollection::open({FontSource{kDejaVu, 0, {}}});
    ASSERT_TRUE(fonts);
    auto added = fonts->add(*face);
    ASSERT_TRUE(added) << added.error().message;
    EXPECT_EQ(fonts->font(*added).face().id(), face->id());
    EXPECT_EQ(fonts->source(*added).file, kDejaVu);
}

TEST(FontFace, FacesOfACollectionFromMemory) {
    const std::vector<std::uint8_t> bytes = read_bytes(kEdgeTtc);
    auto face1 = FontFace::from_memory(bytes.data(), bytes.size(), {1, "edge.ttc"});
    ASSERT_TRUE(face1) << face1.error().message;
    EXPECT_EQ(face1->face_count(), 2);
    auto memory = Font::open(*face1);
    auto file = Font::open(kEdgeTtc, 1);
    ASSERT_TRUE(memory && file);
    EXPECT_EQ(memory->family_name(), file->family_name());
    EXPECT_FALSE(memory->axes().empty());   // face 1 is the variable one
    auto bad = FontFace::from_memory(bytes.data(), bytes.size(), {2, "edge.ttc"});
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, "edge.ttc: face index 2 out of range (the file has 2 faces)");
}

TEST(FontFace, BadBytesAreErrorsNamingTheFont) {
    const std::vector<std::uint8_t> font = read_bytes(kDejaVu);
    const std::vector<std::uint8_t> text(1000, 'x');
    auto not_font = FontFace::from_memory(text.data(), text.size(), {0, "icon-data"});
    ASSERT_FALSE(not_font);
    EXPECT_EQ(not_font.error().message, "icon-data: FreeType error 0x02 (unknown file format)");
    auto empty = FontFace::from_memory(nullptr, 0);
    ASSERT_FALSE(empty);
    EXPECT_EQ(empty.error().message, "<memory>: no font data (empty)");
    auto null_shared = FontFace::from_memory(std::shared_ptr<const std::vector<std::uint8_t>>());
    ASSERT_FALSE(null_shared);
    EXPECT_EQ(null_shared.error().message, "<memory>: no font data (empty)");
    auto negative = FontFace::from_memory(font.data(), font.size(), {-1, "f"});
    ASSERT_FALSE(negative);
    EXPECT_EQ(negative.error().message, "f: face index -1 out of range (0..65535)");
    // Every prefix of a real font opens as an error or as a font whose glyphs load or fail
    // with an error: never a crash (ASan watches the reads).
    for (std::size_t n : {std::size_t{4}, std::size_t{12}, std::size_t{100}, std::size_t{400},
                          std::size_t{5000}, font.size() / 2}) {
        auto face = FontFace::from_memory(font.data(), n, {0, "cut"});
        if (!face) {
            EXPECT_EQ(face.error().message.rfind("cut: ", 0), 0u) << face.error().message;
            continue;
        }
        auto f = Font::open(*face);
        if (!f) continue;
        for (GlyphId g = 0; g < 40 && g < f->glyph_count(); ++g) (void)f->outline(g, {});
        if (auto s = Shaper::open(*face)) (void)s->shape("abc", {});
    }
}

TEST(FontFace, FileErrorsKeepTheirMessages) {
    auto missing = FontFace::open("no/such.ttf");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().message, "no/such.ttf: no such file");
    auto dir = Font::open(BEZEL_FONTS_DIR);
    ASSERT_FALSE(dir);
    EXPECT_EQ(dir.error().message, std::string(BEZEL_FONTS_DIR) + ": is a directory, not a font file");
    auto index = Shaper::open(kDejaVu, 3);
    ASSERT_FALSE(index);
    EXPECT_EQ(index.error().message, kDejaVu + ": face index 3 out of range (the file has 1 face)");
}

// The crash of issue 38: a GlyphRasterizer kept a Font*, and moving the Font away left it
// dangling. It now shares the Font's face.
TEST(GlyphRasterizerLifetime, RasterizerOutlivesAMovedAndDestroyedFont) {
    GlyphRenderOptions o;
    o.size_px = 21;
    std::vector<std::uint8_t> reference;
    GlyphBox reference_box;
    {
        auto font = Font::open(kDejaVu);
        ASSERT_TRUE(font);
        GlyphRasterizer r(*font);
        auto box = r.measure(font->glyph_for_char(U'&').value(), o);
        ASSERT_TRUE(box);
        reference_box = *box;
        reference.assign(static_cast<std::size_t>(box->width * box->height), 0);
        ASSERT_TRUE(r.render(font->glyph_for_char(U'&').value(), o,
                             {reference.data(), box->width, box->height, box->width}));
    }
    std::optional<Font> font(std::move(Font::open(kDejaVu).value()));
    const GlyphId amp = font->glyph_for_char(U'&').value();
    GlyphRasterizer r(*font);
    Font moved = std::move(*font);   // the old crash: r pointed at *font
    font.reset();
    std::vector<std::uint8_t> pixels(reference.size(), 0);
    auto box = r.render(amp, o, {pixels.data(), reference_box.width, reference_box.height,
                                 reference_box.width});
    ASSERT_TRUE(box) << box.error().message;
    EXPECT_EQ(pixels, reference);
    // Destroyed altogether: still drawn, from the shared face.
    { Font gone = std::move(moved); }
    std::fill(pixels.begin(), pixels.end(), 0);
    ASSERT_TRUE(r.render(amp, o, {pixels.data(), reference_box.width, reference_box.height,
                                  reference_box.width}));
    EXPECT_EQ(pixels, reference);
}

TEST(FontMetricsPxTest, PixelMetricsAreFontUnitsScaledAsDistances) {
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    const FontMetrics m = font->metrics();
    auto px = font->metrics_px(20);
    ASSERT_TRUE(px) << px.error().message;
    const double k = 20.0 / m.units_per_em;
    EXPECT_DOUBLE_EQ(px->ascent_px, m.ascender * k);
    EXPECT_DOUBLE_EQ(px->descent_px, -m.descender * k);
    EXPECT_GT(px->ascent_px, 0);
    EXPECT_GT(px->descent_px, 0);
    EXPECT_DOUBLE_EQ(px->line_height_px, px->ascent_px + px->descent_px + px->line_gap_px);
    // HarfBuzz's extents of the same font agree (its ascender is y up, its descender negative).
    auto shaper = Shaper::open(kDejaVu);
    ASSERT_TRUE(shaper);
    ShapeOptions so;
    so.size_px = 20;
    auto e = shaper->extents(so);
    ASSERT_TRUE(e);
    EXPECT_NEAR(px->ascent_px, e->ascender_px, 1.0 / 512);
    EXPECT_NEAR(px->descent_px, -e->descender_px, 1.0 / 512);
    auto bad = font->metrics_px(0);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, kDejaVu + ": font size 0 px out of range (0, 16384]");
}

TEST(OptionDefaults, OutlineGlyphAndShapeOptionsDefaultToOneSize) {
    EXPECT_EQ(OutlineOptions{}.size_px, GlyphRenderOptions{}.size_px);
    EXPECT_EQ(ShapeOptions{}.size_px, GlyphRenderOptions{}.size_px);
    auto font = Font::open(kDejaVu);
    ASSERT_TRUE(font);
    EXPECT_TRUE(font->outline(font->glyph_for_char(U'a').value(), {}));   // no longer size 0
}

TEST(ExpectedAccess, MissingValueThrowsWithBezelsMessage) {
    Expected<Font> missing = Font::open("no/such.ttf");
    ASSERT_FALSE(missing);
    try {
        (void)missing->glyph_count();
        FAIL() << "-> of an error did not throw";
    } catch (const BadExpectedAccess& e) {
        EXPECT_STREQ(e.what(), "bezel: no value: no/such.ttf: no such file");
    }
    EXPECT_THROW((void)*missing, BadExpectedAccess);
    EXPECT_THROW((void)missing.value(), BadExpectedAccess);
    EXPECT_THROW((void)std::move(missing).value(), BadExpectedAccess);
    Status fine = ok_status();
    EXPECT_THROW((void)fine.error(), BadExpectedAccess);
    const Expected<int> number = 3;
    EXPECT_EQ(*number, 3);
}

}  // namespace
}  // namespace bezel
