#!/usr/bin/python3
"""Makes svg-glyph.ttf: DejaVu Sans subset to 'A' and 'B' with an 'SVG ' table giving 'A' an SVG
colour document. bezel does not draw SVG glyphs: tests check that such a glyph is drawn from its
outline with a warning, never silently blank. Run from this folder: /usr/bin/python3 make_svg_font.py
(needs fontTools, Debian's python3-fonttools)."""
from fontTools import subset
from fontTools.ttLib import TTFont, newTable

src = "../../../fonts-test/dejavu-sans/DejaVuSans.ttf"
options = subset.Options()
options.layout_features = []
options.name_IDs = ["*"]
font = TTFont(src)
sub = subset.Subsetter(options)
sub.populate(text="AB")
sub.subset(font)
gid = font.getGlyphID("A")
svg = newTable("SVG ")
doc = ('<svg xmlns="http://www.w3.org/2000/svg"><rect id="glyph%d" x="0" y="-1400" '
       'width="1300" height="1400" fill="#ff0000"/></svg>' % gid)
svg.docList = [(doc, gid, gid)]
font["SVG "] = svg
font.save("svg-glyph.ttf")
