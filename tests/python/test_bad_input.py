"""Abuse: every call with None, wrong types, zero / negative / NaN / huge sizes, invalid UTF-8,
bad SVG, missing and truncated fonts, wrong arrays. Each raises an exception naming what is
wrong (TypeError, ValueError or bezel.Error); none crashes the interpreter."""

import math
import os

import numpy as np
import pytest

import bezel
from bezel import _bezel
from conftest import COLR, DEJAVU

NAN = math.nan
EXPECTED = (TypeError, ValueError, bezel.Error)


def square():
    return bezel.Path("M0 0H4V4H0Z")


def font():
    return bezel.Font(DEJAVU, size=12)


with open(DEJAVU, "rb") as f:
    DEJAVU_BYTES = f.read()

CASES = {
    # Fonts
    "font None": lambda: bezel.Font(None),
    "font int": lambda: bezel.Font(123),
    "font missing": lambda: bezel.Font("/nonexistent/font.ttf"),
    "font directory": lambda: bezel.Font(os.path.dirname(DEJAVU)),
    "font empty bytes": lambda: bezel.Font(b""),
    "font junk bytes": lambda: bezel.Font(b"\x00\x01\x00\x00" + b"junk" * 100),
    "font size 0": lambda: bezel.Font(DEJAVU, size=0),
    "font size -1": lambda: bezel.Font(DEJAVU, size=-1),
    "font size NaN": lambda: bezel.Font(DEJAVU, size=NAN),
    "font size 1e9": lambda: bezel.Font(DEJAVU, size=1e9),
    "font size str": lambda: bezel.Font(DEJAVU, size="12"),
    "font face -1": lambda: bezel.Font(DEJAVU, face_index=-1),
    "font face 1e9": lambda: bezel.Font(DEJAVU, face_index=10**9),
    "font face 1": lambda: bezel.Font(DEJAVU, face_index=1),
    "font variations on a static font": lambda: bezel.Font(DEJAVU, variations={"wght": 700}),
    "font variations tag": lambda: bezel.Font(DEJAVU, variations={"toolong": 1}),
    "font variations NaN": lambda: bezel.Font(DEJAVU, variations={"wght": NAN}),
    "font variations list": lambda: bezel.Font(DEJAVU, variations=[1, 2]),
    "font hinting": lambda: bezel.Font(DEJAVU, hinting="bogus"),
    "font fallback None item": lambda: bezel.Font(DEJAVU, fallback=[None]),
    "font fallback missing": lambda: bezel.Font(DEJAVU, fallback=["/nonexistent.ttf"]),
    "font fallback too many": lambda: bezel.Font(DEJAVU, fallback=[DEJAVU] * 100),
    "font system_fonts int": lambda: bezel.Font(DEJAVU, system_fonts=1),
    # render
    "render None": lambda: font().render(None),
    "render int": lambda: font().render(123),
    "render invalid UTF-8": lambda: font().render(b"ok \xff\xfe"),
    "render lone surrogate": lambda: font().render("\ud800"),
    "render too long": lambda: font().render("a" * ((1 << 24) + 1)),
    "render size 0": lambda: font().render("a", size=0),
    "render size NaN": lambda: font().render("a", size=NAN),
    "render size 1e9": lambda: font().render("a", size=1e9),
    "render width -1": lambda: font().render("a", width=-1),
    "render width NaN": lambda: font().render("a", width=NAN),
    "render width 1e9": lambda: font().render("a", width=1e9),
    "render margin huge page": lambda: font().render("a", margin=30000),
    "render size huge page": lambda: font().render("a" * 200, size=16384),
    "render line_height NaN": lambda: font().render("a", line_height=NAN),
    "render align": lambda: font().render("a", align="middle"),
    "render direction": lambda: font().render("a", direction="up"),
    "render features": lambda: font().render("a", features="@@@"),
    "render features type": lambda: font().render("a", features=5),
    "render script": lambda: font().render("a", script="Xq"),
    "render language": lambda: font().render("a", language="not a tag!"),
    "render foreground name": lambda: font().render("a", foreground="notacolour"),
    "render foreground short": lambda: font().render("a", foreground=(1, 2)),
    "render foreground channel": lambda: font().render("a", foreground=(300, 0, 0)),
    "render foreground float": lambda: font().render("a", foreground=(0.5, 0, 0)),
    "render background None": lambda: font().render("a", background=None),
    "render slant": lambda: font().render("a", slant=5),
    "render bold": lambda: font().render("a", bold=1),
    "render bold NaN": lambda: font().render("a", bold=NAN),
    "render palette -1": lambda: font().render("a", palette=-1),
    "render palette past the font's": lambda: bezel.Font(COLR).render("\U0001F601", palette=99),
    "render custom_palette": lambda: font().render("a", custom_palette={-1: "red"}),
    "render rendering": lambda: font().render("a", rendering="fancy"),
    "render gamma": lambda: font().render("a", gamma=0.5),
    "render gamma with linear": lambda: font().render("a", rendering="linear", gamma=2),
    "render contrast": lambda: font().render("a", contrast=2),
    "render lcd": lambda: font().render("a", lcd="rgbw"),
    "render lcd on transparent": lambda: font().render("a", lcd="rgb", background="transparent"),
    "render mode": lambda: font().render("a", mode="cmyk"),
    "render mode gray in colour": lambda: font().render("a", mode="gray", foreground="red"),
    "render strict": lambda: font().render("あ", strict=True),
    "render unknown keyword": lambda: font().render("a", colour="red"),
    # text_path
    "text_path None": lambda: font().text_path(None),
    "text_path invalid UTF-8": lambda: font().text_path(b"\xc3"),
    "text_path size": lambda: font().text_path("a", size=-3),
    "text_path strict": lambda: font().text_path("あ", strict=True),
    # glyph and outline
    "glyph empty": lambda: font().glyph(""),
    "glyph two characters": lambda: font().glyph("ab"),
    "glyph -1": lambda: font().glyph(-1),
    "glyph 2**40": lambda: font().glyph(2**40),
    "glyph past the font": lambda: font().glyph(10**6),
    "glyph None": lambda: font().glyph(None),
    "glyph float": lambda: font().glyph(1.5),
    "glyph bool": lambda: font().glyph(True),
    "glyph size NaN": lambda: font().glyph("a", size=NAN),
    "glyph offset": lambda: font().glyph("a", offset=(NAN, 0)),
    "glyph offset huge": lambda: font().glyph("a", offset=(1e9, 0)),
    "glyph offset type": lambda: font().glyph("a", offset=3),
    "glyph strict": lambda: font().glyph("あ", strict=True),
    "glyph mode": lambda: font().glyph("a", mode="x"),
    "outline None": lambda: font().outline(None),
    "outline past the font": lambda: font().outline(10**6),
    "outline size 0": lambda: font().outline("a", size=0),
    "outline hinting": lambda: font().outline("a", hinting="max"),
    # Path
    "path None": lambda: bezel.Path(None),
    "path int": lambda: bezel.Path(5),
    "path bad data": lambda: bezel.Path("M 0 0 L x"),
    "path no moveto": lambda: bezel.Path("L 1 1"),
    "path overflow": lambda: bezel.Path("M 1e999 0"),
    "path bounds transform short": lambda: square().bounds((1, 0)),
    "path bounds transform NaN": lambda: square().bounds((1, 0, 0, 1, NAN, 0)),
    "path transformed str": lambda: square().transformed("matrix(1 0 0 1 0 0)"),
    "path transformed overflow": lambda: square().transformed((1e308, 0, 0, 1e308, 0, 0)).transformed((1e308, 0, 0, 1, 0, 0)),
    "path precision": lambda: square().to_svg(precision=0),
    # fill
    "fill None": lambda: bezel.fill(None, 4, 4),
    "fill bad svg": lambda: bezel.fill("M0 0 Q", 4, 4),
    "fill width -1": lambda: bezel.fill(square(), -1, 4),
    "fill width 1e9": lambda: bezel.fill(square(), 10**9, 4),
    "fill width float": lambda: bezel.fill(square(), 4.5, 4),
    "fill height None": lambda: bezel.fill(square(), 4, None),
    "fill transform short": lambda: bezel.fill(square(), 4, 4, transform=(1, 2)),
    "fill transform NaN": lambda: bezel.fill(square(), 4, 4, transform=(NAN, 0, 0, 1, 0, 0)),
    # All floats: the validator's fast path.
    "fill transform float NaN": lambda: bezel.fill(square(), 4, 4,
                                                  transform=(1.0, 0.0, 0.0, 1.0, NAN, 0.0)),
    "bounds transform float inf": lambda: square().bounds((1.0, 0.0, 0.0, float("inf"), 0.0, 0.0)),
    "fill transform huge": lambda: bezel.fill(square(), 4, 4, transform=(1e300, 0, 0, 1e300, 0, 0)),
    "fill rule": lambda: bezel.fill(square(), 4, 4, rule="winding"),
    "fill tolerance 0": lambda: bezel.fill(square(), 4, 4, tolerance=0),
    "fill tolerance NaN": lambda: bezel.fill(square(), 4, 4, tolerance=NAN),
    "fill tolerance -1": lambda: bezel.fill(square(), 4, 4, tolerance=-1),
    "fill out list": lambda: bezel.fill(square(), 4, 4, out=[[0] * 4] * 4),
    "fill out float32": lambda: bezel.fill(square(), 4, 4, out=np.zeros((4, 4), np.float32)),
    "fill out 3-D": lambda: bezel.fill(square(), 4, 4, out=np.zeros((4, 4, 1), np.uint8)),
    "fill out wrong shape": lambda: bezel.fill(square(), 4, 4, out=np.zeros((4, 5), np.uint8)),
    "fill out strided columns": lambda: bezel.fill(square(), 4, 4,
                                                   out=np.zeros((4, 8), np.uint8)[:, ::2]),
    "fill out transposed": lambda: bezel.fill(square(), 4, 4, out=np.zeros((4, 4), np.uint8).T),
    # encode_png
    "png None": lambda: bezel.encode_png(None),
    "png list": lambda: bezel.encode_png([[0, 1]]),
    "png float": lambda: bezel.encode_png(np.zeros((2, 2))),
    "png bool": lambda: bezel.encode_png(np.zeros((2, 2, 4), bool)),
    "png 1-D": lambda: bezel.encode_png(np.zeros(4, np.uint8)),
    "png two channels": lambda: bezel.encode_png(np.zeros((2, 2, 2), np.uint8)),
    "png empty": lambda: bezel.encode_png(np.zeros((0, 5), np.uint8)),
    "png too large": lambda: bezel.encode_png(np.broadcast_to(np.uint8(0), (1, 40000))),
    "png compression": lambda: bezel.encode_png(np.zeros((2, 2), np.uint8), compression=9),
}


def _read_only():
    out = np.zeros((4, 4), np.uint8)
    out.setflags(write=False)
    return bezel.fill(square(), 4, 4, out=out)


CASES["fill out read-only"] = _read_only


@pytest.mark.parametrize("name", sorted(CASES))
def test_bad_input_raises_a_named_error(name):
    with pytest.raises(EXPECTED + (UnicodeError,)) as caught:
        CASES[name]()
    assert str(caught.value), name


def test_errors_carry_bezels_message():
    with pytest.raises(bezel.Error, match="/nonexistent/font.ttf"):
        bezel.Font("/nonexistent/font.ttf")
    with pytest.raises(bezel.Error, match="text byte 3: invalid UTF-8"):
        font().render(b"ok \xff")
    with pytest.raises(bezel.Error, match="path data offset"):
        bezel.Path("M0 0 L1")
    with pytest.raises(ValueError, match="size"):
        font().render("a", size=0)
    assert issubclass(bezel.Error, Exception) and bezel.Error.__module__ == "bezel"


@pytest.mark.parametrize("cut", [12, 100, 1000, 20000, len(DEJAVU_BYTES) // 2])
def test_truncated_font_bytes_raise_or_draw(cut):
    # A font cut short may open (FreeType reads tables lazily) and fail per glyph: an Error,
    # never a crash.
    try:
        f = bezel.Font(DEJAVU_BYTES[:cut], size=16)
        f.render("Truncated font")
        f.glyph("g")
        f.outline("g")
    except bezel.Error as e:
        assert "<bytes>" in str(e)


def test_private_layer_checks_its_arguments_too():
    core = bezel.Font(DEJAVU)._core
    calls = [
        lambda: _bezel.FontCore([], False),
        lambda: _bezel.FontCore([("x",)], False),
        lambda: _bezel.FontCore([(5, 0, [])], False),
        lambda: _bezel.FontCore([(DEJAVU, -1, [])], False),
        lambda: _bezel.FontCore([(DEJAVU, 0, [(1, 2)])], False),
        lambda: core.render(123, {}, "auto", 16.0, "none"),
        lambda: core.render("a", {"size": "big"}, "auto", 16.0, "none"),
        lambda: core.render("a", {"foreground": (1, 2, 3)}, "auto", 16.0, "none"),
        lambda: core.render("a", {"foreground": (1, 2, 3, 999)}, "auto", 16.0, "none"),
        lambda: core.render("a", {"custom_palette": [(0,)]}, "auto", 16.0, "none"),
        lambda: core.render("a", {}, "auto", NAN, "none"),
        lambda: core.render("a", {}, "auto", 16.0, "bogus"),
        lambda: core.glyph(-5, True, {}, "auto", 16.0, "none"),
        lambda: core.glyph(0xD800, True, {}, "auto", 16.0, "none"),
        lambda: core.glyph(1, False, {"offset_x": NAN}, "auto", 16.0, "none"),
        lambda: core.outline(1, False, -1.0, "none"),
        lambda: core.text_path("a", {"bold": 0.1}, 16.0, "none"),
        lambda: _bezel.fill(_bezel.Path(), -1, 1, None, "nonzero", 0.01, None),
        lambda: _bezel.fill(_bezel.Path(), 1, 1, (1, 2, 3), "nonzero", 0.01, None),
        lambda: _bezel.fill(_bezel.Path(), 1, 1, None, "nonzero", NAN, None),
        lambda: _bezel.fill(_bezel.Path(), 2, 2, None, "nonzero", 0.01, np.zeros((2, 2), np.int16)),
        lambda: _bezel.encode_png(np.zeros((2, 2), np.uint8), "best"),
        lambda: _bezel.Path().svg(99),
        lambda: _bezel.parse_color("#12"),
    ]
    for k, call in enumerate(calls):
        with pytest.raises(EXPECTED):
            call()


# Fuzz-style: each keyword of each call given values from a pool of hostile ones, drawn by a
# seeded generator: every call returns or raises one of the expected exceptions.
HOSTILE = [None, -1, 0, NAN, math.inf, 1e9, 2**70, -(2**70), "", "\x00", "a" * 300, b"\xff\xfe",
           [], [1, 2], (1, 2, 3, 4, 5, 6, 7), {}, object(), True, 1.5, (0, 0), (NAN, 0)]
RENDER_KEYWORDS = ["size", "width", "margin", "line_height", "align", "direction", "features",
                   "script", "language", "foreground", "background", "slant", "bold", "color",
                   "palette", "custom_palette", "rendering", "gamma", "contrast", "lcd", "hinting",
                   "strict", "mode"]
GLYPH_KEYWORDS = ["size", "hinting", "slant", "bold", "offset", "color", "palette",
                  "custom_palette", "foreground", "strict", "mode"]
FILL_KEYWORDS = ["transform", "rule", "tolerance", "out"]


def test_random_hostile_keywords_never_crash():
    import random
    import warnings
    rng = random.Random(37)
    f = font()
    calls = [
        (lambda kw: f.render("Ab", **kw), RENDER_KEYWORDS),
        (lambda kw: f.text_path("Ab", **{k: v for k, v in kw.items()
                                         if k in ("size", "width", "margin", "line_height",
                                                  "align", "direction", "features", "script",
                                                  "language", "slant", "hinting", "strict")}),
         RENDER_KEYWORDS),
        (lambda kw: f.glyph("g", **kw), GLYPH_KEYWORDS),
        (lambda kw: bezel.fill(square(), 6, 6, **kw), FILL_KEYWORDS),
    ]
    outcomes = {"ok": 0, "raised": 0}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for _ in range(600):
            call, keywords = rng.choice(calls)
            chosen = rng.sample(keywords, rng.randint(1, 3))
            kw = {k: rng.choice(HOSTILE) for k in chosen}
            try:
                call(kw)
                outcomes["ok"] += 1
            except EXPECTED + (UnicodeError,) as e:
                assert str(e), kw
                outcomes["raised"] += 1
    assert outcomes["raised"] > 300 and outcomes["ok"] > 0, outcomes
