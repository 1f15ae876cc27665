#!/usr/bin/python3
"""Writes BitmapStrike.ttf: an outline font with embedded monochrome and gray bitmap strikes
(EBLC/EBDT), for bezel's tests of GlyphRenderOptions::embedded_bitmaps (see README.md).

Run with Debian's /usr/bin/python3 (package python3-fonttools) from any directory:
    /usr/bin/python3 fonts-test/bitmap-strike/make_font.py
The output is deterministic (fixed timestamps).

The bitmaps are deliberately NOT the outlines rasterized: a test can tell at a glance which of
the two was drawn. 'A' and 'B' are filled rectangles as outlines; as bitmaps they are a
checkerboard (A, 16 ppem, 1 bit), a frame (B, 16 ppem, 1 bit) and a horizontal ramp of gray
levels (A, 20 ppem, 8 bits). 'B' has no image in the 20 ppem strike (it falls back to its
outline there).
"""
import os
import tempfile

from fontTools.fontBuilder import FontBuilder
from fontTools.ttLib.tables import ttProgram
from fontTools.ttLib.tables._g_l_y_f import Glyph, GlyphCoordinates, flagOnCurve

HERE = os.path.dirname(os.path.abspath(__file__))
UPEM = 1000
FIXED_TIMESTAMP = 3660681600  # 2020-01-01T00:00:00Z since 1904-01-01


def rectangle(x0, y0, x1, y1):
    g = Glyph()
    g.numberOfContours = 1
    g.coordinates = GlyphCoordinates([(x0, y0), (x0, y1), (x1, y1), (x1, y0)])
    g.flags = bytearray([flagOnCurve] * 4)
    g.endPtsOfContours = [3]
    g.program = ttProgram.Program()
    g.program.fromBytecode(b"")
    return g


def empty_glyph():
    g = Glyph()
    g.numberOfContours = 0
    return g


# Bitmaps: rows top to bottom, each a list of pixel values (0/1 for 1 bit, 0..255 for 8 bits).
CHECKER = [[(x + y) % 2 for x in range(8)] for y in range(10)]
FRAME = [[1 if x in (0, 6) or y in (0, 9) else 0 for x in range(7)] for y in range(10)]
RAMP = [[x * 255 // 9 for x in range(10)] for _ in range(12)]


def row_hex(row, bit_depth):
    if bit_depth == 8:
        return "".join("%02x" % v for v in row)
    data = bytearray((len(row) + 7) // 8)
    for x, v in enumerate(row):
        if v:
            data[x // 8] |= 0x80 >> (x % 8)
    return data.hex()


def glyph_xml(name, rows, bit_depth, bearing_x, bearing_y, advance):
    height, width = len(rows), len(rows[0])
    lines = ['<ebdt_bitmap_format_1 name="%s">' % name,
             "<SmallGlyphMetrics>",
             '<height value="%d"/><width value="%d"/>' % (height, width),
             '<BearingX value="%d"/><BearingY value="%d"/><Advance value="%d"/>'
             % (bearing_x, bearing_y, advance),
             "</SmallGlyphMetrics>",
             '<rowimagedata bitDepth="%d" width="%d" height="%d">' % (bit_depth, width, height)]
    lines += ['<row value="%s"/>' % row_hex(r, bit_depth) for r in rows]
    lines += ["</rowimagedata>", "</ebdt_bitmap_format_1>"]
    return "\n".join(lines)


def line_metrics(direction, ppem):
    names = ["ascender", "descender", "widthMax", "caretSlopeNumerator", "caretSlopeDenominator",
             "caretOffset", "minOriginSB", "minAdvanceSB", "maxBeforeBL", "minAfterBL", "pad1",
             "pad2"]
    values = {"ascender": ppem * 8 // 10, "descender": -(ppem * 2 // 10), "widthMax": ppem,
              "caretSlopeNumerator": 1 if direction == "hori" else 0,
              "caretSlopeDenominator": 0 if direction == "hori" else 1}
    body = "".join('<%s value="%d"/>' % (n, values.get(n, 0)) for n in names)
    return '<sbitLineMetrics direction="%s">%s</sbitLineMetrics>' % (direction, body)


def strike_xml(index, ppem, bit_depth, names, glyph_ids):
    first, last = glyph_ids[names[0]], glyph_ids[names[-1]]
    return "\n".join([
        '<strike index="%d">' % index,
        "<bitmapSizeTable>",
        line_metrics("hori", ppem), line_metrics("vert", ppem),
        '<colorRef value="0"/>',
        '<startGlyphIndex value="%d"/><endGlyphIndex value="%d"/>' % (first, last),
        '<ppemX value="%d"/><ppemY value="%d"/>' % (ppem, ppem),
        '<bitDepth value="%d"/><flags value="1"/>' % bit_depth,
        "</bitmapSizeTable>",
        '<eblc_index_sub_table_1 imageFormat="1" firstGlyphIndex="%d" lastGlyphIndex="%d">'
        % (first, last)]
        + ['<glyphLoc name="%s"/>' % n for n in names]
        + ["</eblc_index_sub_table_1>", "</strike>"])


def main():
    order = [".notdef", "space", "A", "B"]
    glyph_ids = {name: i for i, name in enumerate(order)}
    fb = FontBuilder(UPEM, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({ord(" "): "space", ord("A"): "A", ord("B"): "B"})
    glyphs = {".notdef": empty_glyph(), "space": empty_glyph(),
              "A": rectangle(100, 0, 600, 700), "B": rectangle(100, 0, 500, 600)}
    fb.setupGlyf(glyphs)
    advances = {".notdef": 500, "space": 250, "A": 700, "B": 600}
    for name in order:
        glyphs[name].recalcBounds(fb.font["glyf"])
    fb.setupHorizontalMetrics({n: (advances[n], getattr(glyphs[n], "xMin", 0)) for n in order})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "Bezel Bitmap Strike", "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, sTypoDescender=-200, sTypoLineGap=100,
                usWinAscent=800, usWinDescent=200)
    fb.setupPost()
    fb.font["head"].created = FIXED_TIMESTAMP
    fb.font["head"].modified = FIXED_TIMESTAMP
    fb.font.recalcTimestamp = False

    ebdt = ['<EBDT>', '<header version="2.0"/>',
            '<strikedata index="0">',
            glyph_xml("A", CHECKER, 1, 1, 10, 11), glyph_xml("B", FRAME, 1, 2, 10, 10),
            '</strikedata>',
            '<strikedata index="1">',
            glyph_xml("A", RAMP, 8, 2, 12, 14),
            '</strikedata>', '</EBDT>']
    eblc = ['<EBLC>', '<header version="2.0"/>',
            strike_xml(0, 16, 1, ["A", "B"], glyph_ids),
            strike_xml(1, 20, 8, ["A"], glyph_ids), '</EBLC>']
    xml = ('<?xml version="1.0" encoding="UTF-8"?>\n<ttFont sfntVersion="\\x00\\x01\\x00\\x00">\n'
           + "\n".join(ebdt + eblc) + "\n</ttFont>\n")
    with tempfile.NamedTemporaryFile("w", suffix=".ttx", delete=False) as f:
        f.write(xml)
    try:
        fb.font.importXML(f.name)
    finally:
        os.remove(f.name)
    fb.save(os.path.join(HERE, "BitmapStrike.ttf"))


if __name__ == "__main__":
    main()
