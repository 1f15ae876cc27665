#!/usr/bin/python3
"""Writes the tiny edge-case fonts bezel's font tests load (see README.md beside this file).

Run with Debian's /usr/bin/python3 (package python3-fonttools) from any directory:
    /usr/bin/python3 fonts-test/edge-cases/make_fonts.py
The output is deterministic: timestamps are fixed, so re-running gives the same bytes and a
changed file in `git status` means the script changed.

Glyphs are built point by point (not with a pen) because the point structure *is* the test:
which points are on-curve, where a contour starts, how many points it has.
"""
import os

from fontTools.fontBuilder import FontBuilder
from fontTools.ttLib import TTFont
from fontTools.ttLib.tables import ttProgram
from fontTools.ttLib.tables._g_l_y_f import (Glyph, GlyphComponent, GlyphCoordinates,
                                           flagOnCurve, flagOverlapSimple)
from fontTools.ttLib.tables.TupleVariation import TupleVariation
from fontTools.ttLib.ttCollection import TTCollection

HERE = os.path.dirname(os.path.abspath(__file__))
UPEM = 1000
# 2020-01-01T00:00:00Z in seconds since 1904-01-01 (the OpenType epoch).
FIXED_TIMESTAMP = 3660681600

ON, OFF = True, False


def simple_glyph(contours, overlap=False):
    """contours: list of lists of (x, y, on_curve), in font units, y up."""
    coords, flags, ends = [], [], []
    for contour in contours:
        for x, y, on in contour:
            coords.append((x, y))
            flags.append(flagOnCurve if on else 0)
        ends.append(len(coords) - 1)
    if overlap and flags:
        # OpenType: OVERLAP_SIMPLE is set on the first point's flags.
        flags[0] |= flagOverlapSimple
    g = Glyph()
    g.numberOfContours = len(contours)
    g.coordinates = GlyphCoordinates(coords)
    g.flags = bytearray(flags)
    g.endPtsOfContours = ends
    g.program = ttProgram.Program()
    g.program.fromBytecode(b"")
    return g


def empty_glyph():
    g = Glyph()
    g.numberOfContours = 0
    return g


def composite_glyph(components):
    """components: list of (glyph_name, dx, dy, scale or None)."""
    g = Glyph()
    g.numberOfContours = -1
    g.components = []
    for name, dx, dy, scale in components:
        c = GlyphComponent()
        c.glyphName = name
        c.x, c.y = dx, dy
        c.flags = 0x0001 | 0x0002  # ARG_1_AND_2_ARE_WORDS | ARGS_ARE_XY_VALUES
        if scale is not None:
            c.transform = [[scale, 0.0], [0.0, scale]]
        g.components.append(c)
    return g


def finish(fb, advances, path):
    glyf = fb.font["glyf"]
    metrics = {}
    for name in fb.font.getGlyphOrder():
        g = glyf[name]
        g.recalcBounds(glyf)
        metrics[name] = (advances[name], getattr(g, "xMin", 0))
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupOS2(sTypoAscender=800, sTypoDescender=-200, sTypoLineGap=100,
                usWinAscent=800, usWinDescent=200)
    fb.setupPost()
    fb.font["head"].created = FIXED_TIMESTAMP
    fb.font["head"].modified = FIXED_TIMESTAMP
    fb.font.recalcTimestamp = False
    fb.save(path)


def make_edge_cases(path):
    glyphs = {
        ".notdef": simple_glyph([[(50, 0, ON), (50, 700, ON), (450, 700, ON), (450, 0, ON)],
                                 [(100, 50, ON), (400, 50, ON), (400, 650, ON), (100, 650, ON)]]),
        "space": empty_glyph(),
        # Only off-curve points: four implied on-curve midpoints, the first between the last and
        # the first point. Odd sums (100 + 501) make the midpoints fall between font units.
        "A": simple_glyph([[(100, 100, OFF), (100, 501, OFF), (501, 501, OFF), (501, 100, OFF)]]),
        # Contour 0 starts off-curve and ends on-curve; contour 1 starts and ends off-curve with
        # an on-curve point between (it starts at the implied midpoint (150, 250.5)).
        "B": simple_glyph([[(150, 700, OFF), (350, 700, ON), (450, 600, OFF), (450, 500, ON),
                            (150, 500, ON)],
                           [(150, 400, OFF), (450, 400, ON), (450, 100, OFF), (150, 101, OFF)]]),
        # A single on-curve point, a triangle, and a single off-curve point.
        "period": simple_glyph([[(250, 300, ON)],
                                [(100, 0, ON), (250, 150, ON), (400, 0, ON)],
                                [(250, 400, OFF)]]),
        # Two overlapping squares, flagged OVERLAP_SIMPLE.
        "O": simple_glyph([[(100, 100, ON), (100, 500, ON), (500, 500, ON), (500, 100, ON)],
                           [(300, 300, ON), (300, 700, ON), (700, 700, ON), (700, 300, ON)]],
                          overlap=True),
        # 'A' shifted right by 50, and 'O' at half size shifted to (600, 200).
        "C": composite_glyph([("A", 50, 0, None), ("O", 600, 200, 0.5)]),
    }
    order = [".notdef", "space", "A", "B", "C", "O", "period"]
    advances = {".notdef": 500, "space": 300, "A": 600, "B": 600, "C": 1000, "O": 800,
                "period": 500}
    fb = FontBuilder(UPEM, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({ord(" "): "space", ord("A"): "A", ord("B"): "B", ord("C"): "C",
                          ord("O"): "O", ord("."): "period"})
    fb.setupGlyf({name: glyphs[name] for name in order})
    fb.setupNameTable({"familyName": "Bezel Edge Cases", "styleName": "Regular"})
    finish(fb, advances, path)


def make_variable(path):
    order = [".notdef", "I"]
    glyphs = {
        ".notdef": simple_glyph([[(50, 0, ON), (50, 700, ON), (450, 700, ON), (450, 0, ON)]]),
        # A bar whose right edge (points 2 and 3) moves with wght.
        "I": simple_glyph([[(100, 0, ON), (100, 700, ON), (300, 700, ON), (300, 0, ON)]]),
    }
    fb = FontBuilder(UPEM, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({ord("I"): "I"})
    fb.setupGlyf(glyphs)
    # fvar names its axis and instances in the name table, so it must exist first.
    fb.setupNameTable({"familyName": "Bezel Variable", "styleName": "Regular"})
    fb.setupFvar(axes=[("wght", 100, 400, 900, "Weight")],
                 instances=[dict(location=dict(wght=400), stylename="Regular"),
                            dict(location=dict(wght=900), stylename="Black")])
    # Deltas for the four points, then the four phantom points (left side bearing, advance,
    # top, bottom): at wght 900 the bar and the advance widen by 200 units, at 100 narrow by 100.
    heavy = [(0, 0), (0, 0), (200, 0), (200, 0), (0, 0), (200, 0), (0, 0), (0, 0)]
    light = [(0, 0), (0, 0), (-100, 0), (-100, 0), (0, 0), (-100, 0), (0, 0), (0, 0)]
    fb.setupGvar({"I": [TupleVariation({"wght": (0.0, 1.0, 1.0)}, heavy),
                        TupleVariation({"wght": (-1.0, -1.0, 0.0)}, light)]})
    finish(fb, {".notdef": 500, "I": 400}, path)


def make_collection(path, members):
    ttc = TTCollection()
    ttc.fonts = [TTFont(m, recalcTimestamp=False) for m in members]
    ttc.save(path)


if __name__ == "__main__":
    edge = os.path.join(HERE, "EdgeCases.ttf")
    var = os.path.join(HERE, "EdgeCasesVariable.ttf")
    make_edge_cases(edge)
    make_variable(var)
    make_collection(os.path.join(HERE, "EdgeCases.ttc"), [edge, var])
