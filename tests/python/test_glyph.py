"""Font.glyph and Font.outline: metrics as the font states them, bitmaps equal to the fill of
the outline, colour glyphs in RGBA."""

import math

import numpy as np
import pytest

import bezel
from conftest import COLR, DEJAVU, font_path

EDGE = font_path("edge-cases/EdgeCases.ttf")


def test_outline_metrics_are_the_fonts():
    # EdgeCases.ttf: 1000 units per em, advances A 600, C 1000, space 300; A's contour spans
    # (100, 100)-(501, 501) in font units, y up (fonts-test/edge-cases/README.md).
    font = bezel.Font(EDGE, size=1000)
    a = font.outline("A")
    assert a.advance == pytest.approx(600) and a.gid > 0 and a.font == 0
    # Four off-curve points only: the curve runs through the implied midpoints of the box's
    # sides, which are its extremes (y down: the font's y 501 is -501 px).
    assert a.bounds == pytest.approx((100, -501, 501, -100))
    assert font.outline("C").advance == pytest.approx(1000)
    space = font.outline(" ")
    assert space.advance == pytest.approx(300) and space.bounds is None and space.segments == []
    half = bezel.Font(EDGE, size=500).outline("A")
    assert half.advance == pytest.approx(300)


def test_outline_segments_and_svg_agree():
    outline = bezel.Font(DEJAVU, size=40).outline("S")
    assert outline.segments and all(k in ("line", "quad", "cubic") for k, _ in outline.segments)
    for kind, points in outline.segments:
        assert len(points) == {"line": 2, "quad": 3, "cubic": 4}[kind]
    again = bezel.Path(outline.svg)
    assert again == outline.path and again.segments == outline.segments


def test_glyph_bitmap_is_the_fill_of_its_outline():
    font = bezel.Font(DEJAVU, size=33)
    for ch in "aSg@":
        glyph = font.glyph(ch)
        outline = font.outline(ch)
        h, w = glyph.image.shape
        # Pixel (0, 0) of the bitmap is at pen + (left, -top): move the outline there.
        filled = bezel.fill(outline.svg, w, h, transform=(1, 0, 0, 1, -glyph.left, glyph.top))
        assert np.array_equal(filled, glyph.image), ch
        # The tight box: whole pixels around the outline's bounds.
        x0, y0, x1, y1 = outline.bounds
        assert glyph.left == math.floor(x0) and -glyph.top == math.floor(y0)
        assert w == math.ceil(x1) - math.floor(x0) and h == math.ceil(y1) - math.floor(y0)
        assert glyph.advance == pytest.approx(outline.advance)


def test_glyph_advances_lay_out_text():
    font = bezel.Font(DEJAVU, size=20)
    advance = font.glyph("H").advance
    assert font.render("H" * 10).shape[1] == math.ceil(10 * advance)


def test_glyph_by_id_and_space():
    font = bezel.Font(DEJAVU, size=20)
    by_char = font.glyph("A")
    by_id = font.glyph(by_char.gid)
    assert by_id.gid == by_char.gid and np.array_equal(by_id.image, by_char.image)
    space = font.glyph(" ")
    assert space.image.shape == (0, 0) and space.advance > 0
    with pytest.raises(bezel.Error, match="glyph"):
        font.glyph(font.glyph_count)


def test_subpixel_offset_moves_the_ink():
    font = bezel.Font(DEJAVU, size=24)
    plain = font.glyph("l")
    moved = font.glyph("l", offset=(0.5, 0))
    assert not np.array_equal(plain.image, moved.image) or plain.left != moved.left
    assert moved.image.sum() == pytest.approx(plain.image.sum(), rel=0.01)


def test_colour_glyph_is_straight_rgba():
    font = bezel.Font(COLR, size=48)
    glyph = font.glyph("\U0001F601")
    assert glyph.color and glyph.image.ndim == 3 and glyph.image.shape[2] == 4
    alpha = glyph.image[:, :, 3]
    assert alpha.max() == 255
    # Straight alpha: an opaque pixel's colour is unchanged, a transparent one carries none.
    assert (glyph.image[alpha == 0][:, :3] == 0).all()
    gray = font.glyph("\U0001F601", mode="gray")
    assert gray.image.ndim == 2 and np.array_equal(gray.image, alpha)


def test_mask_glyph_in_rgba_is_coverage_times_foreground():
    glyph = bezel.Font(DEJAVU, size=20).glyph("o", mode="rgba", foreground="#ff8000")
    cov = bezel.Font(DEJAVU, size=20).glyph("o")
    assert glyph.image.shape == cov.image.shape + (4,)
    assert np.array_equal(glyph.image[:, :, 3], cov.image)
    # Opaque pixels carry the colour exactly (8-bit premultiplied colour cannot give it back
    # exactly where alpha is small).
    solid = cov.image == 255
    assert solid.any() and (glyph.image[solid][:, :3] == (255, 128, 0)).all()


def test_glyph_images_are_not_copies():
    image = bezel.Font(DEJAVU, size=20).glyph("W").image
    assert not image.flags.owndata and type(image.base).__name__ == "PyCapsule"
