"""Font.text_path: the laid-out text as one path, placed where render() draws it."""

import math

import numpy as np
import pytest

import bezel
from conftest import DEJAVU


def linear_ink(page):
    """Coverage a black-on-white page with rendering="linear" was drawn with: 1 − linear light."""
    v = page.astype(np.float64) / 255
    light = np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
    return 1 - light


def test_text_path_fills_to_the_rendered_page(dejavu):
    text = "Wafer office\nflow"
    tp = dejavu.text_path(text, size=28, margin=5)
    page = dejavu.render(text, size=28, margin=5, rendering="linear")
    assert (tp.height, tp.width) == page.shape
    filled = bezel.fill(tp.path, tp.width, tp.height).astype(np.float64) / 255
    ink = linear_ink(page)
    # render() places pens at quarter pixels (the glyph cache's bins), the path at the exact
    # pens: the total ink agrees closely, and no pixel is more than a stroke edge apart.
    assert filled.sum() == pytest.approx(ink.sum(), rel=0.01)
    assert np.abs(filled - ink).max() < 0.5
    x0, y0, x1, y1 = tp.ink_bounds
    rows = np.nonzero(ink.sum(axis=1) > 0.01)[0]
    cols = np.nonzero(ink.sum(axis=0) > 0.01)[0]
    assert abs(math.floor(y0) - rows[0]) <= 1 and abs(math.ceil(x1) - 1 - cols[-1]) <= 1


def test_text_path_baseline_is_the_first_lines():
    font = bezel.Font(DEJAVU, size=40)
    tp = font.text_path("H", margin=10)
    # The first baseline is at margin + ascender; H stands on it.
    assert tp.baseline == pytest.approx(10 + font.ascender_px)
    assert tp.ink_bounds[3] == pytest.approx(tp.baseline)


def test_rotated_fill_keeps_the_area(dejavu):
    tp = dejavu.text_path("Rotate me", size=30, margin=20)
    flat = float(bezel.fill(tp.path, tp.width, tp.height).sum())
    a = math.radians(7)
    cx, cy = tp.width / 2, tp.height / 2
    c, s = math.cos(a), math.sin(a)
    # Rotation about the page centre: x' = c·x − s·y + e, y' = s·x + c·y + f.
    m = (c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy)
    turned = bezel.fill(tp.path, tp.width, tp.height, transform=m)
    assert float(turned.sum()) == pytest.approx(flat, rel=0.01)
    assert tp.path.bounds(m) is not None


def test_text_path_refuses_synthetic_bold(dejavu):
    with pytest.raises(TypeError):
        dejavu.text_path("bold", bold=0.1)   # not an option of text_path


def test_text_path_outlines_reused_across_calls_match_a_fresh_font():
    """A Font keeps the glyph outlines text_path loaded for later calls (keyed by font, glyph,
    size, hinting and slant): every call, in any order, equals a fresh Font's first call."""
    cases = [dict(size=16), dict(size=24), dict(size=16, slant=0.2), dict(size=16, hinting="full"),
             dict(size=16)]
    text = "Hamburgefonstiv Hg"
    shared = bezel.Font(DEJAVU)
    svgs = []
    for options in cases:
        got = shared.text_path(text, **options)
        fresh = bezel.Font(DEJAVU).text_path(text, **options)
        assert got.path.svg == fresh.path.svg, options
        assert (got.width, got.height, got.ink_bounds) == (fresh.width, fresh.height,
                                                           fresh.ink_bounds), options
        svgs.append(got.path.svg)
    assert len(set(svgs[:4])) == 4 and svgs[4] == svgs[0]
