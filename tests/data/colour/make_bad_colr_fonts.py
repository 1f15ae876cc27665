#!/usr/bin/python3
"""Makes the small COLR test fonts of tests/color_glyph_test.cpp (run from anywhere; writes
beside this script; needs fontTools, Debian's python3-fonttools):

  colr_v0.ttf           COLR version 0 with a CPAL version 1 of two palettes (light, dark):
                        glyph "stack" = square (entry 0), triangle (entry 1), square in the
                        foreground colour (0xFFFF).
  colr_loop.ttf         COLR version 1 graphs that loop: "self" is PaintColrGlyph(self); "ping"
                        is PaintColrGlyph(pong) and "pong" PaintColrGlyph(ping).
  colr_deep.ttf         COLR version 1 glyph "deep": 10,000 PaintRotate (angle 0) nested, then
                        PaintGlyph(square, PaintSolid). Its COLR table is written byte by byte
                        here (fontTools' compiler recurses once per level).
  colr_wide.ttf         COLR version 1 glyph "wide": 17 PaintComposite nested, each with source
                        and backdrop the same child, then PaintSolid: 18 levels deep, but
                        painting it visits 2^18 - 1 nodes (the node budget's case).
  colr_stops.ttf        COLR version 1 glyph "stops": 5 PaintComposite nested as in colr_wide
                        over PaintGlyph(square, PaintLinearGradient) whose colour line holds
                        2100 stops: 32 gradients reached, 67,200 stops in all.
  sbix_huge.ttf         sbix strike (100 ppem) whose glyph "huge" is a PNG declaring 5000 × 5000
                        pixels (100 MB of RGBA, past kMaxColorBitmapBytes) with no pixel data:
                        refused from its header, never decoded.
  svg.ttf               an 'SVG ' table whose one document draws glyph "drawn" (for
                        color_format's Svg; bezel does not draw SVG glyphs in colour).
  colr_bad_palette.ttf  CPAL with 2 entries; "bad_solid" (version 1) paints PaintSolid with
                        palette index 7, "bad_layer" (version 0) a layer with palette index 9.

The outputs are committed; run again only to change them.
"""
import os
import struct
import zlib

from fontTools.colorLib.builder import buildCOLR, buildCPAL
from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib.tables.DefaultTable import DefaultTable

HERE = os.path.dirname(os.path.abspath(__file__))
UPEM = 1000
DEPTH = 10000


def polygon(points):
    pen = TTGlyphPen(None)
    pen.moveTo(points[0])
    for p in points[1:]:
        pen.lineTo(p)
    pen.closePath()
    return pen.glyph()


def empty():
    return TTGlyphPen(None).glyph()


def base_font(colour_glyphs):
    """A font with .notdef, square, triangle and the named (empty-outline) colour glyphs."""
    order = [".notdef", "square", "triangle"] + colour_glyphs
    glyphs = {".notdef": empty(),
              "square": polygon([(100, 0), (100, 800), (900, 800), (900, 0)]),
              "triangle": polygon([(100, 0), (500, 800), (900, 0)])}
    for name in colour_glyphs:
        glyphs[name] = empty()
    fb = FontBuilder(UPEM, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({0x41 + i: name for i, name in enumerate(colour_glyphs)})
    fb.setupGlyf(glyphs)
    # Left side bearings are the outlines' xMin (100 for both shapes), as FreeType expects.
    fb.setupHorizontalMetrics({name: (1000, 100 if name in ("square", "triangle") else 0) for name in order})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "bezel COLR test", "styleName": "Regular"})
    fb.setupOS2()
    fb.setupPost()
    # Fixed head dates (2024-01-01, seconds since 1904), so that running the script again writes
    # the same bytes.
    fb.updateHead(created=3786825600, modified=3786825600)
    fb.font.recalcTimestamp = False
    return fb


def solid(index, alpha=1.0):
    return {"Format": 2, "PaletteIndex": index, "Alpha": alpha}


def make_v0():
    fb = base_font(["stack"])
    fb.font["CPAL"] = buildCPAL(
        [[(1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 0.5)], [(0.0, 1.0, 0.0, 1.0), (1.0, 1.0, 0.0, 1.0)]],
        paletteTypes=[1, 2])   # 1: for light backgrounds, 2: for dark
    fb.font["COLR"] = buildCOLR({"stack": [("square", 0), ("triangle", 1), ("square", 0xFFFF)]}, version=0)
    fb.save(os.path.join(HERE, "colr_v0.ttf"))


def make_loop():
    fb = base_font(["self", "ping", "pong"])
    fb.font["CPAL"] = buildCPAL([[(1.0, 0.0, 0.0, 1.0)]])
    fb.font["COLR"] = buildCOLR({
        "self": {"Format": 11, "Glyph": "self"},
        "ping": {"Format": 11, "Glyph": "pong"},
        "pong": {"Format": 11, "Glyph": "ping"},
    }, version=1)
    fb.save(os.path.join(HERE, "colr_loop.ttf"))


def make_deep():
    fb = base_font(["deep"])
    fb.font["CPAL"] = buildCPAL([[(1.0, 0.0, 0.0, 1.0)]])
    deep_gid = fb.font.getGlyphID("deep")
    square_gid = fb.font.getGlyphID("square")
    # COLR version 1 header: version, numBaseGlyphRecords, Offset32 baseGlyphRecords, Offset32
    # layerRecords, numLayerRecords, then Offset32 BaseGlyphList, LayerList, ClipList,
    # VarIndexMap, ItemVariationStore.
    header = struct.pack(">HHIIHIIIII", 1, 0, 0, 0, 0, 34, 0, 0, 0, 0)
    # BaseGlyphList: count, then (glyphID, Offset32 paint from the list's start).
    base_list = struct.pack(">IHI", 1, deep_gid, 10)
    # PaintRotate: format 24, Offset24 to its child (the next table, 6 bytes on), angle 0.
    rotate = struct.pack(">B", 24) + (6).to_bytes(3, "big") + struct.pack(">h", 0)
    # PaintGlyph: format 10, Offset24 paint (6 bytes on), glyphID; PaintSolid: format 2,
    # paletteIndex 0, alpha 1.0 (F2Dot14 0x4000).
    glyph = struct.pack(">B", 10) + (6).to_bytes(3, "big") + struct.pack(">H", square_gid)
    paint_solid = struct.pack(">BHh", 2, 0, 0x4000)
    colr = DefaultTable("COLR")
    colr.data = header + base_list + rotate * DEPTH + glyph + paint_solid
    fb.font["COLR"] = colr
    fb.save(os.path.join(HERE, "colr_deep.ttf"))


def make_wide():
    fb = base_font(["wide"])
    fb.font["CPAL"] = buildCPAL([[(1.0, 0.0, 0.0, 1.0)]])
    header = struct.pack(">HHIIHIIIII", 1, 0, 0, 0, 0, 34, 0, 0, 0, 0)
    base_list = struct.pack(">IHI", 1, fb.font.getGlyphID("wide"), 10)
    # PaintComposite: format 32, Offset24 source, mode 3 (src_over), Offset24 backdrop; both
    # offsets name the next table, 8 bytes on.
    composite = struct.pack(">B", 32) + (8).to_bytes(3, "big") + struct.pack(">B", 3) + (8).to_bytes(3, "big")
    paint_solid = struct.pack(">BHh", 2, 0, 0x4000)
    colr = DefaultTable("COLR")
    colr.data = header + base_list + composite * 17 + paint_solid
    fb.font["COLR"] = colr
    fb.save(os.path.join(HERE, "colr_wide.ttf"))


def make_stops():
    fb = base_font(["stops"])
    fb.font["CPAL"] = buildCPAL([[(1.0, 0.0, 0.0, 1.0)]])
    header = struct.pack(">HHIIHIIIII", 1, 0, 0, 0, 0, 34, 0, 0, 0, 0)
    base_list = struct.pack(">IHI", 1, fb.font.getGlyphID("stops"), 10)
    composite = struct.pack(">B", 32) + (8).to_bytes(3, "big") + struct.pack(">B", 3) + (8).to_bytes(3, "big")
    glyph = struct.pack(">B", 10) + (6).to_bytes(3, "big") + struct.pack(">H", fb.font.getGlyphID("square"))
    # PaintLinearGradient: format 4, Offset24 colour line (right after its 16 bytes), six FWORDs.
    linear = struct.pack(">B", 4) + (16).to_bytes(3, "big") + struct.pack(">6h", 0, 0, 1000, 0, 0, 1000)
    # ColorLine: extend pad, numStops, then (F2Dot14 offset, paletteIndex, F2Dot14 alpha).
    stops = 2100
    line = struct.pack(">BH", 0, stops) + b"".join(struct.pack(">hHh", i * 16384 // stops, 0, 0x4000)
                                                    for i in range(stops))
    colr = DefaultTable("COLR")
    colr.data = header + base_list + composite * 5 + glyph + linear + line
    fb.font["COLR"] = colr
    fb.save(os.path.join(HERE, "colr_stops.ttf"))


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def make_sbix_huge():
    from fontTools.ttLib import newTable
    from fontTools.ttLib.tables.sbixGlyph import Glyph as SbixGlyph
    from fontTools.ttLib.tables.sbixStrike import Strike
    fb = base_font(["huge"])
    # IHDR: width, height, bit depth 8, colour type 6 (RGBA), compression, filter, interlace.
    png = (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", struct.pack(">IIBBBBB", 5000, 5000, 8, 6, 0, 0, 0)) +
           png_chunk(b"IDAT", zlib.compress(b"")) + png_chunk(b"IEND", b""))
    sbix = newTable("sbix")
    strike = Strike(ppem=100, resolution=72)
    for name in fb.font.getGlyphOrder():
        strike.glyphs[name] = SbixGlyph(glyphName=name)
    strike.glyphs["huge"] = SbixGlyph(glyphName="huge", graphicType="png ", originOffsetX=0, originOffsetY=0,
                                      imageData=png)
    sbix.strikes[100] = strike
    fb.font["sbix"] = sbix
    fb.save(os.path.join(HERE, "sbix_huge.ttf"))


def make_svg():
    from fontTools.ttLib import newTable
    from fontTools.ttLib.tables.S_V_G_ import SVGDocument
    fb = base_font(["drawn"])
    gid = fb.font.getGlyphID("drawn")
    svg = newTable("SVG ")
    svg.docList = [SVGDocument('<svg xmlns="http://www.w3.org/2000/svg"><rect id="glyph%d" x="100" y="-800" '
                               'width="800" height="800" fill="red"/></svg>' % gid, gid, gid)]
    fb.font["SVG "] = svg
    fb.save(os.path.join(HERE, "svg.ttf"))


def make_bad_palette():
    fb = base_font(["bad_solid", "bad_layer"])
    fb.font["CPAL"] = buildCPAL([[(1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0)]])
    fb.font["COLR"] = buildCOLR({
        "bad_solid": {"Format": 10, "Glyph": "square", "Paint": solid(7)},
        "bad_layer": [("square", 0), ("triangle", 9)],
    })   # no version: fontTools puts the layer list in version 0 records
    fb.save(os.path.join(HERE, "colr_bad_palette.ttf"))


if __name__ == "__main__":
    make_v0()
    make_loop()
    make_deep()
    make_wide()
    make_stops()
    make_sbix_huge()
    make_svg()
    make_bad_palette()
