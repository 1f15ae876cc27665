"""Font.render: the pages equal the C++ library's own (`bezel render` of the same build), in
both forms (gray and RGBA), without copies, and with the layout options of the CLI."""

import io
import warnings

import numpy as np
import pytest

import bezel
from conftest import ARABIC, CJK, COLR, DEJAVU, VARIABLE, read_pgm


def test_gray_page_equals_the_cli_render(dejavu, cli):
    text = "Wafer office, 2 × 3"
    page = dejavu.render(text, size=24, margin=3)
    expected = read_pgm(cli("render", DEJAVU, text, "--font-size", "24", "--margin", "3",
                            "--no-system-fonts", "-O", "pgm"))
    assert page.dtype == np.uint8 and page.ndim == 2
    assert np.array_equal(page, expected)


@pytest.mark.parametrize("options,flags", [
    ({"features": "-liga"}, ["--features=-liga"]),
    ({"width": 120, "align": "center"}, ["--width", "120", "--align", "center"]),
    ({"line_height": 1.5, "width": 80}, ["--line-height", "1.5", "--width", "80"]),
    ({"slant": 0.2, "bold": 0.04}, ["--font-slant", "0.2", "--font-bold", "0.04"]),
    ({"rendering": "linear"}, ["--rendering", "linear"]),
    ({"gamma": 1.8, "contrast": 0.5}, ["--gamma", "1.8", "--contrast", "0.5"]),
    ({"foreground": "#404040", "background": (200, 200, 200)},
     ["--foreground", "#404040", "--background", "#c8c8c8"]),
    ({"hinting": "full"}, ["--hinting", "full"]),
    ({"direction": "ttb"}, ["--direction", "ttb"]),
])
def test_layout_options_mirror_the_cli(dejavu, cli, options, flags):
    text = "office flow\nwafer"
    page = dejavu.render(text, size=18, margin=2, **options)
    expected = read_pgm(cli("render", DEJAVU, text, "--font-size", "18", "--margin", "2",
                            "--no-system-fonts", "-O", "pgm", *flags))
    assert np.array_equal(page, expected)


def test_options_change_the_page(dejavu):
    plain = dejavu.render("office", size=30)
    assert not np.array_equal(plain, dejavu.render("office", size=30, features="-liga")) \
        or plain.shape != dejavu.render("office", size=30, features="-liga").shape
    wrapped = dejavu.render("one two three four", size=20, width=60)
    assert wrapped.shape[0] > dejavu.render("one two three four", size=20).shape[0]


def test_rtl_text_equals_the_cli(cli):
    font = bezel.Font(ARABIC, size=28)
    text = "مرحبا بالعالم"
    page = font.render(text, margin=4)
    expected = read_pgm(cli("render", ARABIC, text, "--font-size", "28", "--margin", "4",
                            "--no-system-fonts", "-O", "pgm"))
    assert np.array_equal(page, expected)


def test_colour_text_is_rgba_equal_to_the_cli(dejavu, cli):
    from PIL import Image
    text = "Colour"
    page = dejavu.render(text, size=24, margin=2, foreground="#c02020", background="ivory")
    assert page.shape[2] == 4 and page.dtype == np.uint8
    png = cli("render", DEJAVU, text, "--font-size", "24", "--margin", "2", "--no-system-fonts",
              "--foreground", "#c02020", "--background", "ivory", "-O", "png")
    expected = np.array(Image.open(io.BytesIO(png)).convert("RGBA"))
    assert np.array_equal(page, expected)


def test_rgba_mode_of_gray_text_repeats_the_gray_page(dejavu):
    gray = dejavu.render("Gray", size=22)
    rgba = dejavu.render("Gray", size=22, mode="rgba")
    assert rgba.shape == gray.shape + (4,)
    for c in range(3):
        assert np.array_equal(rgba[:, :, c], gray)
    assert (rgba[:, :, 3] == 255).all()


def test_translucent_background_keeps_alpha(dejavu):
    page = dejavu.render("A", size=30, background="transparent")
    assert page.ndim == 3
    assert page[0, 0, 3] == 0 and page[:, :, 3].max() == 255


def test_colour_glyphs_make_an_rgba_page():
    font = bezel.Font(COLR, size=64)
    assert font.has_color
    page = font.render("\U0001F601")
    assert page.ndim == 3
    rgb = page[:, :, :3].astype(int)
    # Twemoji's smiley is yellow: pixels far from gray.
    assert (np.abs(rgb[:, :, 0] - rgb[:, :, 2]) > 100).any()
    # color=False draws the outline's coverage instead: a gray page.
    assert font.render("\U0001F601", color=False, strict=False).ndim == 2


def test_pages_are_not_copies(dejavu):
    page = dejavu.render("Zero copy", size=20)
    # The array wraps the library's own buffer (owned through a capsule), not numpy's.
    assert not page.flags.owndata
    assert type(page.base).__name__ == "PyCapsule"
    assert page.flags.c_contiguous and page.flags.writeable
    rgba = dejavu.render("Zero copy", size=20, mode="rgba")
    assert not rgba.flags.owndata and rgba.strides == (rgba.shape[1] * 4, 4, 1)


def test_pillow_reads_the_arrays_without_conversion(dejavu):
    from PIL import Image
    gray = dejavu.render("Pillow", size=20)
    image = Image.fromarray(gray)
    assert image.mode == "L" and np.array_equal(np.asarray(image), gray)
    rgba = dejavu.render("Pillow", size=20, foreground="navy")
    image = Image.fromarray(rgba)
    assert image.mode == "RGBA" and np.array_equal(np.asarray(image), rgba)


def test_missing_glyphs_warn_or_fail_when_strict(dejavu):
    with pytest.warns(bezel.MissingGlyphWarning, match="no glyph for U\\+3042"):
        dejavu.render("aあ")
    with pytest.raises(bezel.Error, match="no glyph for U\\+3042"):
        dejavu.render("aあ", strict=True)


def test_fallback_fonts_draw_what_the_first_lacks():
    font = bezel.Font(DEJAVU, size=24, fallback=[CJK])
    assert font.fonts == [DEJAVU, CJK]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        page = font.render("aあ", strict=True)
    alone = bezel.Font(DEJAVU, size=24)
    with pytest.warns(bezel.MissingGlyphWarning):
        notdef = alone.render("aあ")
    assert not np.array_equal(page, notdef)
    assert font.glyph("あ").font == 1 and font.glyph("a").font == 0


def test_fonts_from_bytes_render_like_files(dejavu):
    with open(DEJAVU, "rb") as f:
        data = f.read()
    font = bezel.Font(data, size=20)
    assert font.path is None and font.fonts == ["<bytes>"]
    assert np.array_equal(font.render("bytes"), dejavu.render("bytes"))


def test_bytes_text_is_utf8(dejavu):
    assert np.array_equal(dejavu.render("é".encode()), dejavu.render("é"))


def test_font_facts(dejavu):
    assert dejavu.family == "DejaVu Sans" and dejavu.units_per_em == 2048
    assert dejavu.size == 20 and dejavu.path == DEJAVU and not dejavu.has_color
    assert dejavu.glyph_count > 1000 and dejavu.face_count == 1 and dejavu.axes == []
    assert 0 < dejavu.descender_px < dejavu.ascender_px < 20
    # One line of text is as tall as the font's line height, rounded up to whole pixels.
    assert dejavu.render("Hg").shape[0] == int(np.ceil(dejavu.line_height_px))


def test_variable_font_axes_and_variations():
    # EdgeCasesVariable: one axis, wght 100..400..900; its "I" is a bar whose right edge and
    # advance move by +200 units at 900 (fonts-test/edge-cases/README.md). 1000 units per em,
    # so at 1000 px a unit is a pixel.
    font = bezel.Font(VARIABLE, size=1000)
    assert font.axes == [bezel.Axis("wght", "Weight", 100.0, 400.0, 900.0)]
    assert font.outline("I").advance == pytest.approx(400)
    black = bezel.Font(VARIABLE, size=1000, variations={"wght": 900})
    assert black.outline("I").advance == pytest.approx(600)
    assert black.outline("I").bounds == pytest.approx((100, -700, 500, 0))
    # The page grows with the advance: render and outline see the same coordinates.
    small = bezel.Font(VARIABLE, size=100, variations={"wght": 900})
    assert small.render("II").shape[1] == 120
    with pytest.raises(bezel.Error, match="wdth"):
        bezel.Font(VARIABLE, variations={"wdth": 100})


def test_collection_faces():
    from conftest import font_path
    ttc = font_path("edge-cases/EdgeCases.ttc")
    assert bezel.Font(ttc).family == "Bezel Edge Cases"
    second = bezel.Font(ttc, face_index=1)
    assert second.family == "Bezel Variable" and second.face_count == 2
    with pytest.raises(bezel.Error, match="face"):
        bezel.Font(ttc, face_index=2)


def test_lcd_text_equals_the_cli(dejavu, cli):
    from PIL import Image
    page = dejavu.render("LCD text", size=16, margin=2, lcd="bgr")
    assert page.ndim == 3
    png = cli("render", DEJAVU, "LCD text", "--font-size", "16", "--margin", "2",
              "--no-system-fonts", "--lcd", "bgr", "-O", "png")
    assert np.array_equal(page, np.array(Image.open(io.BytesIO(png)).convert("RGBA")))
    # Subpixel text has colour fringes: the channels differ somewhere.
    assert (page[:, :, 0] != page[:, :, 2]).any()


def test_custom_palette_equals_the_cli(cli):
    from PIL import Image
    font = bezel.Font(COLR, size=48)
    plain = font.render("\U0001F601")
    recoloured = font.render("\U0001F601", custom_palette={4: "blue", 10: (0, 128, 0)})
    assert not np.array_equal(plain, recoloured)
    png = cli("render", COLR, "\U0001F601", "--font-size", "48", "--margin", "0",
              "--no-system-fonts", "--custom-palette", "4=blue,10=#008000", "-O", "png")
    assert np.array_equal(recoloured, np.array(Image.open(io.BytesIO(png)).convert("RGBA")))


def test_fonts_and_paths_pickle():
    import pickle
    font = bezel.Font(DEJAVU, size=21, hinting="light", fallback=[bezel.Font(CJK)])
    again = pickle.loads(pickle.dumps(font))
    assert again.size == 21 and again.hinting == "light" and again.fonts == font.fonts
    assert np.array_equal(again.render("aあ"), font.render("aあ"))
    with open(DEJAVU, "rb") as f:
        from_bytes = bezel.Font(f.read(), size=12)
    assert np.array_equal(pickle.loads(pickle.dumps(from_bytes)).render("b"), from_bytes.render("b"))
    path = font.outline("S").path
    assert pickle.loads(pickle.dumps(path)) == path


def test_missing_glyph_warnings_follow_the_warnings_filters(dejavu):
    with warnings.catch_warnings():
        warnings.simplefilter("error", bezel.MissingGlyphWarning)
        with pytest.raises(bezel.MissingGlyphWarning):
            dejavu.render("あ")
        with pytest.raises(bezel.MissingGlyphWarning):
            dejavu.glyph("あ")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bezel.MissingGlyphWarning)
        assert dejavu.glyph("あ").gid == 0   # the .notdef box


def test_system_fonts_are_asked_only_when_enabled():
    # Off (the default), a character no listed font has is always the .notdef box, whatever the
    # machine's fonts. On, fontconfig is asked: a system font draws it (appended to the list),
    # or, where none has it (ctest runs with a configuration without fonts), it stays missing.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bezel.MissingGlyphWarning)
        alone = bezel.Font(DEJAVU, size=16).glyph("あ")
    assert (alone.font, alone.gid) == (0, 0)
    font = bezel.Font(DEJAVU, size=16, system_fonts=True)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        glyph = font.glyph("あ")
    missing = [w for w in caught if issubclass(w.category, bezel.MissingGlyphWarning)]
    assert (glyph.font >= 1 and glyph.gid > 0 and not missing) or (glyph.gid == 0 and missing)


@pytest.mark.parametrize("compression", ["fast", "default", "small"])
@pytest.mark.parametrize("shape", [(1, 1), (1, 739), (28, 739), (5, 3, 4), (1, 739, 4),
                                   (28, 739, 3), (200, 31, 4)])
def test_encode_png_round_trips_through_pillow(shape, compression):
    """Every level and layout decodes (by Pillow) to the array's exact bytes: the one-stream
    igzip writer (fast, default), libpng (small), gray, RGB and RGBA, 1-row images."""
    from PIL import Image
    rng = np.random.default_rng(37)
    a = rng.integers(0, 256, size=shape, dtype=np.uint8)
    a[..., ::3] = 200  # runs of one value, as on a text line
    back = np.array(Image.open(io.BytesIO(bezel.encode_png(a, compression=compression))))
    assert back.shape == a.shape and np.array_equal(back, a)
