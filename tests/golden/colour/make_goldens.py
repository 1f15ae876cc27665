#!/usr/bin/python3
"""Reference renderings of colour glyphs by Chromium (Skia), for tests/colour_golden_test.cpp.

Run through make_goldens.sh (which states the requirements). Steps:
  1. `cells`: enumerate what to draw. Every COLRv1 base glyph of test_glyphs-glyf_colr_1.ttf that the
     cmap reaches, at 64 and 128 px; the CBDT glyph of the Noto Color Emoji subset and the sbix
     glyphs of the two sbix fonts (samples-sbix's are GSUB ligatures, drawn from their spelling),
     at 32 and 128 px.
  2. `page`: an HTML page that loads each font by @font-face (as a data: URL, so that a file://
     page may use it) and, once document.fonts.load says it is ready, draws each cell into a canvas
     of its own: opaque white, black text colour, ctx.font `${px}px <family>`, textBaseline
     'alphabetic', fillText at the integer pen origin. The page writes every canvas out as
     toDataURL('image/png') in one JSON text, which `chromium --dump-dom` prints.
  3. `extract`: decodes those PNGs (libpng's simplified API through ctypes: the system Python has no
     PIL), checks each is opaque, and writes it as gray when every pixel is, else RGB, deflated at
     zlib level 9, with the manifest.

The cell geometry is the same for every glyph of a size, so the test can place bezel's rendering
the same way: the pen origin in CELL PIXELS (y down), the glyph's em box [0, px] x [0, px] above it.
"""
import base64
import ctypes
import json
import struct
import sys
import zlib
from pathlib import Path

import numpy as np
from fontTools.ttLib import TTFont

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
OUT = HERE / "chromium"
MANIFEST = HERE / "manifest.tsv"

COLR_FONT = "fonts-test/colour/test_glyphs-glyf_colr_1.ttf"
BITMAP_FONTS = [
    ("CBDT", "fonts-test/noto-color-emoji/NotoColorEmoji-subset.ttf"),
    ("sbix", "fonts-test/colour/twemoji_smiley-sbix.ttf"),
    ("sbix", "fonts-test/colour/samples-sbix.ttf"),
]
COLR_SIZES_PX = (64, 128)
BITMAP_SIZES_PX = (32, 128)

# Cell geometry in ems: the pen origin sits MARGIN_LEFT_EM from the left edge and ASCENT_EM below
# the top; the cell is WIDTH_EM x HEIGHT_EM. Chosen from the ink of every cell rendered first with
# a 1 em margin all round: x in [-0.125, 1.219] em, y in [-0.250, 1.125] em (the scale, translate
# and skew tests reach outside the em box; `extract` prints the span each time), so each side
# keeps at least 0.125 em of white.
MARGIN_LEFT_EM = 0.25
ASCENT_EM = 1.25
WIDTH_EM = 1.625
HEIGHT_EM = 1.625


def cell_geometry(px):
    """(width, height, pen_x, pen_y) in pixels, all integers."""
    return (round(WIDTH_EM * px), round(HEIGHT_EM * px), round(MARGIN_LEFT_EM * px),
            round(ASCENT_EM * px))


def colr_cells():
    font = TTFont(ROOT / COLR_FONT)
    colr = font["COLR"].table
    by_glyph = {}
    for cp, name in font.getBestCmap().items():
        by_glyph.setdefault(name, []).append(cp)
    cells = []
    for rec in colr.BaseGlyphList.BaseGlyphPaintRecord:
        name = rec.BaseGlyph
        if name not in by_glyph:
            continue   # reachable only through another glyph's PaintColrGlyph
        cp = min(by_glyph[name])
        for px in COLR_SIZES_PX:
            cells.append(dict(format="COLRv1", font=COLR_FONT, name=name,
                              gid=font.getGlyphID(name), text=[cp], px=px))
    return cells


def bitmap_glyphs(font):
    """Names of the glyphs that have a colour bitmap in some strike."""
    names = set()
    if "sbix" in font:
        for strike in font["sbix"].strikes.values():
            names.update(n for n, g in strike.glyphs.items() if g.graphicType)
    if "CBDT" in font:
        for strike in font["CBDT"].strikeData:
            names.update(strike.keys())
    return names


def ligature_spellings(font):
    """{ligature glyph name: its component glyph names}, from GSUB's ligature lookups."""
    spell = {}
    if "GSUB" not in font:
        return spell
    for lookup in font["GSUB"].table.LookupList.Lookup:
        for sub in lookup.SubTable:
            for first, ligs in getattr(sub, "ligatures", {}).items():
                for lig in ligs:
                    spell.setdefault(lig.LigGlyph, [first] + list(lig.Component))
    return spell


def bitmap_cells():
    cells = []
    for fmt, path in BITMAP_FONTS:
        font = TTFont(ROOT / path)
        cp_of = {}
        for cp, name in font.getBestCmap().items():
            cp_of.setdefault(name, cp)
        spell = ligature_spellings(font)
        for name in sorted(bitmap_glyphs(font), key=font.getGlyphID):
            if name in cp_of:
                text = [cp_of[name]]
            elif name in spell and all(c in cp_of for c in spell[name]):
                text = [cp_of[c] for c in spell[name]]
            else:
                continue
            for px in BITMAP_SIZES_PX:
                cells.append(dict(format=fmt, font=path, name=name, gid=font.getGlyphID(name),
                                  text=text, px=px))
    return cells


def all_cells():
    cells = colr_cells() + bitmap_cells()
    fonts = []
    for c in cells:
        if c["font"] not in fonts:
            fonts.append(c["font"])
        c["family"] = "F%d" % fonts.index(c["font"])
        c["w"], c["h"], c["x"], c["y"] = cell_geometry(c["px"])
        stem = Path(c["font"]).stem
        c["file"] = "%s-%s-%d.png" % (stem, c["name"], c["px"])
    return cells, fonts


PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><style>
%(faces)s
body { margin: 0; background: white; }
</style></head><body><pre id="out">pending</pre><script>
const cells = %(cells)s;
const families = %(families)s;
async function main() {
  for (const f of families) {
    const faces = await document.fonts.load('32px ' + f);
    if (faces.length !== 1) throw new Error('font ' + f + ' did not load');
  }
  const out = {};
  for (const c of cells) {
    const canvas = document.createElement('canvas');
    canvas.width = c.w; canvas.height = c.h;
    const ctx = canvas.getContext('2d');
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, c.w, c.h);
    ctx.fillStyle = '#000000';
    ctx.font = c.px + 'px ' + c.family;
    ctx.textBaseline = 'alphabetic';
    ctx.textAlign = 'left';
    ctx.fillText(String.fromCodePoint(...c.text), c.x, c.y);
    out[c.file] = canvas.toDataURL('image/png');
  }
  document.getElementById('out').textContent = 'DONE' + JSON.stringify(out);
}
main().catch(e => { document.getElementById('out').textContent = 'FAILED ' + e; });
</script></body></html>
"""


def write_page(html_path):
    cells, fonts = all_cells()
    faces = "\n".join(
        "@font-face { font-family: F%d; src: url(data:font/ttf;base64,%s) format('truetype'); }"
        % (i, base64.b64encode((ROOT / f).read_bytes()).decode()) for i, f in enumerate(fonts))
    page_cells = [{k: c[k] for k in ("family", "text", "px", "w", "h", "x", "y", "file")}
                  for c in cells]
    Path(html_path).write_text(PAGE % dict(faces=faces, cells=json.dumps(page_cells),
                                           families=json.dumps(["F%d" % i for i in
                                                                range(len(fonts))])))


# --- PNG decoding (libpng's simplified API) and encoding (by hand, zlib level 9) -----------------
class PngImage(ctypes.Structure):
    _fields_ = [("opaque", ctypes.c_void_p), ("version", ctypes.c_uint32),
                ("width", ctypes.c_uint32), ("height", ctypes.c_uint32),
                ("format", ctypes.c_uint32), ("flags", ctypes.c_uint32),
                ("colormap_entries", ctypes.c_uint32), ("warning_or_error", ctypes.c_uint32),
                ("message", ctypes.c_char * 64)]


PNG_IMAGE_VERSION = 1
PNG_FORMAT_RGBA = 3   # PNG_FORMAT_FLAG_COLOR | PNG_FORMAT_FLAG_ALPHA
_libpng = ctypes.CDLL("libpng16.so.16")


def decode_png_rgba(data):
    img = PngImage(version=PNG_IMAGE_VERSION)
    if not _libpng.png_image_begin_read_from_memory(ctypes.byref(img), data, len(data)):
        raise ValueError("libpng: " + img.message.decode())
    img.format = PNG_FORMAT_RGBA
    buf = ctypes.create_string_buffer(4 * img.width * img.height)
    if not _libpng.png_image_finish_read(ctypes.byref(img), None, buf, 0, None):
        raise ValueError("libpng: " + img.message.decode())
    return img.width, img.height, buf.raw


def encode_png(path, width, height, channels, pixels):
    """8-bit gray (channels 1) or RGB (3) PNG; each row's filter the one of None, Sub, Up with the
    smallest sum of absolute bytes (libpng's heuristic, without Average and Paeth)."""
    img = np.frombuffer(pixels, np.uint8).reshape(height, width * channels)
    sub = img.copy()
    sub[:, channels:] -= img[:, :-channels]
    up = img.copy()
    up[1:] -= img[:-1]

    def cost(a):   # bytes read as signed
        return np.minimum(a, 256 - a.astype(np.int32)).sum(axis=1)
    choice = np.argmin(np.stack([cost(img), cost(sub), cost(up)]), axis=0)
    rows = np.where(choice[:, None] == 0, img, np.where(choice[:, None] == 1, sub, up))
    raw = np.concatenate([choice.astype(np.uint8)[:, None], rows], axis=1).tobytes()

    def chunk(tag, body):
        return (struct.pack(">I", len(body)) + tag + body +
                struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF))
    colour_type = 0 if channels == 1 else 2
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" +
                           chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type,
                                                      0, 0, 0)) +
                           chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def extract(dom_path, chromium_version):
    cells, _ = all_cells()
    dom = Path(dom_path).read_text()
    start = dom.find("DONE")
    if start < 0:
        failed = dom.find("FAILED")
        raise SystemExit("make_goldens: the page did not finish: " +
                         (dom[failed:failed + 200] if failed >= 0 else "no result in the DOM"))
    end = dom.find("</pre>", start)
    urls = json.loads(dom[start + 4:end].replace("&amp;", "&").replace("&lt;", "<")
                      .replace("&gt;", ">").replace("&quot;", '"'))
    OUT.mkdir(exist_ok=True)
    for old in OUT.glob("*.png"):
        old.unlink()
    rows = []
    for c in cells:
        w, h, rgba = decode_png_rgba(base64.b64decode(urls[c["file"]].split(",", 1)[1]))
        if (w, h) != (c["w"], c["h"]):
            raise SystemExit("make_goldens: %s is %dx%d, not %dx%d" % (c["file"], w, h, c["w"],
                                                                      c["h"]))
        px = np.frombuffer(rgba, np.uint8).reshape(h, w, 4)
        if (px[:, :, 3] != 255).any():
            raise SystemExit("make_goldens: %s is not opaque" % c["file"])
        rgb = px[:, :, :3]
        if (rgb == 255).all():
            print("make_goldens: warning: %s is blank" % c["file"], file=sys.stderr)
        ink = np.argwhere((rgb != 255).any(axis=2))
        if len(ink):
            (y0, x0), (y1, x1) = ink.min(axis=0), ink.max(axis=0) + 1
            c["ink_em"] = ((x0 - c["x"]) / c["px"], (c["y"] - y1) / c["px"],
                           (x1 - c["x"]) / c["px"], (c["y"] - y0) / c["px"])
        gray = (rgb[:, :, 0] == rgb[:, :, 1]).all() and (rgb[:, :, 1] == rgb[:, :, 2]).all()
        encode_png(OUT / c["file"], w, h, 1 if gray else 3,
                   (rgb[:, :, 0] if gray else rgb).tobytes())
        rows.append(c)
    with open(MANIFEST, "w") as m:
        m.write("# Colour glyphs drawn by %s (Skia) on a white canvas, black text colour; "
                "made by make_goldens.sh.\n" % chromium_version)
        m.write("# Pen origin and cell in pixels, y down; text: the code points drawn.\n")
        m.write("format\tfont\tglyph\tgid\ttext\tpx\tcell_w\tcell_h\tpen_x\tpen_y\tfile\n")
        for c in rows:
            m.write("\t".join([c["format"], c["font"], c["name"], str(c["gid"]),
                               " ".join("U+%04X" % cp for cp in c["text"]), str(c["px"]),
                               str(c["w"]), str(c["h"]), str(c["x"]), str(c["y"]),
                               "chromium/" + c["file"]]) + "\n")
    inked = [c["ink_em"] for c in rows if "ink_em" in c]
    print("make_goldens: %d cells written to %s; ink in em (glyph space, y up): x [%.3f, %.3f], "
          "y [%.3f, %.3f]" % (len(rows), OUT, min(i[0] for i in inked), max(i[2] for i in inked),
                              min(i[1] for i in inked), max(i[3] for i in inked)))


if __name__ == "__main__":
    if sys.argv[1:2] == ["page"] and len(sys.argv) == 3:
        write_page(sys.argv[2])
    elif sys.argv[1:2] == ["extract"] and len(sys.argv) == 4:
        extract(sys.argv[2], sys.argv[3])
    else:
        raise SystemExit("usage: make_goldens.py page OUT.html | extract DOM.html CHROMIUM_VERSION")
