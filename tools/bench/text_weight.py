#!/usr/bin/env python3
"""Text weight of `bezel render` against hb-view: the same text, font, size and margins, drawn
dark on light and light on dark, compared by ink.

Ink of a page: the sum over its pixels of (255 - value) for dark-on-light, of value for
light-on-dark (the margins and the background add nothing). The ratio bezel / hb-view says how
heavy bezel's text looks against hb-view's (cairo, which mixes coverage into the sRGB-encoded
bytes as they are). "peak" is the strongest pixel: the darkest value dark-on-light, the brightest
light-on-dark.

hb-view 6 draws unhinted outlines (--ft-load-flags defaults to 2, FT_LOAD_NO_HINTING) with gray
antialiasing, --font-size is the em size in pixels, and its margin is 16 px like bezel's: so both
draw the same outlines at the same size, and the pages have the same size (hb-view's is at most
a column wider, which the ink does not see).

Usage:
  tools/bench/text_weight.py [--bezel PATH] [--sizes 8,10,12] [--fonts A.ttf,B.otf]
                             [--reference FILE] [--pictures DIR] [-- BEZEL RENDER OPTIONS...]
Everything after `--` goes to `bezel render` (e.g. `-- --rendering linear`). --reference FILE
writes hb-view's figures as the test data tests/text_weight_test.cpp reads. Needs only python3
(PNG is decoded here with zlib) and hb-view (Debian libharfbuzz-bin).
"""
import argparse
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_FONTS = [
    os.path.join(ROOT, "fonts-test/dejavu-sans/DejaVuSans.ttf"),
    os.path.join(ROOT, "fonts-test/cantarell/Cantarell-Regular.otf"),
]
# A pangram with capitals and figures: every lowercase letter, round and straight stems.
DEFAULT_TEXT = "The quick brown fox jumps over the lazy dog 0123456789"
POLARITIES = {"dark": ("#000000", "#FFFFFF"), "light": ("#FFFFFF", "#000000")}


def read_png_gray(path):
    """(width, height, rows of bytes) of an 8-bit PNG, the first channel of each pixel (the
    pages measured here are gray, whatever layout the writer chose)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG")
    pos, idat, width = 8, [], None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or interlace != 0:
                raise ValueError(path + ": only 8-bit, non-interlaced PNG is read here")
            channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
        elif kind == b"IDAT":
            idat.append(body)
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(bytes(line[::channels]))
        prev = line
    return width, height, rows


def ink(path, polarity):
    """(ink, peak, width, height) of a page."""
    width, height, rows = read_png_gray(path)
    total, peak = 0, None
    for row in rows:
        if polarity == "dark":
            total += 255 * len(row) - sum(row)
            peak = min(row) if peak is None else min(peak, min(row))
        else:
            total += sum(row)
            peak = max(row) if peak is None else max(peak, max(row))
    return total, peak, width, height


def write_png_gray(path, width, rows):
    """An 8-bit gray PNG of `rows` (bytes of `width` each), unfiltered."""
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))
    raw = b"".join(b"\0" + row for row in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" +
                chunk(b"IHDR", struct.pack(">IIBBBBB", width, len(rows), 8, 0, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def pictures(args, font, sizes, folder, tmp):
    """For each polarity, three pictures of the text at every size, one line per size (margin 4
    px): hb-view's, bezel's linear and bezel's default rendering, for the docs."""
    for polarity, (fg, bg) in POLARITIES.items():
        for name, command in (
                ("hbview", [args.hb_view, font]),
                ("linear", [args.bezel, "render", font, "--rendering", "linear"]),
                ("default", [args.bezel, "render", font])):
            lines, width = [], 0
            for px in sizes:
                png = os.path.join(tmp, "line.png")
                subprocess.run(command + ["--text", args.text, "--font-size", str(px),
                                          "--margin", "4", "--foreground", fg, "--background",
                                          bg, "-o", png], check=True)
                w, _, rows = read_png_gray(png)
                width = max(width, w)
                lines.append(rows)
            fill = 255 if polarity == "dark" else 0
            rows = [row + bytes([fill]) * (width - len(row)) for line in lines for row in line]
            write_png_gray(os.path.join(folder, f"weight-{name}-{polarity}.png"), width, rows)


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bezel", default=os.environ.get(
        "BEZEL", os.path.join(ROOT, "build/release/tools/bezel/bezel")))
    ap.add_argument("--hb-view", default="hb-view")
    ap.add_argument("--fonts", default=",".join(DEFAULT_FONTS))
    ap.add_argument("--sizes", default="8,10,12,16,20,24")
    ap.add_argument("--text", default=DEFAULT_TEXT)
    ap.add_argument("--reference", help="write hb-view's figures here (test data)")
    ap.add_argument("--pictures", metavar="DIR",
                    help="also write the docs' pictures of the first font here")
    args = ap.parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",")]
    fonts = args.fonts.split(",")
    hb_version = subprocess.run([args.hb_view, "--version"], capture_output=True,
                                text=True).stdout.splitlines()[0]
    # hb-view's pixels are cairo's and FreeType's: name their versions where dpkg knows them.
    libs = subprocess.run(["dpkg-query", "-W", "-f", "${Package} ${Version}, ", "libcairo2",
                           "libfreetype6"], capture_output=True, text=True).stdout.rstrip(", ")
    if libs:
        hb_version += " with " + libs

    reference = []
    print("font\tpx\tpolarity\tbezel_ink\thb_ink\tratio\tbezel_peak\thb_peak")
    worst = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for font in fonts:
            for px in sizes:
                for polarity, (fg, bg) in POLARITIES.items():
                    hb_png = os.path.join(tmp, "hb.png")
                    bz_png = os.path.join(tmp, "bz.png")
                    subprocess.run([args.hb_view, font, "--text", args.text,
                                    "--font-size", str(px), "--margin", "16",
                                    "--foreground", fg, "--background", bg, "-o", hb_png],
                                   check=True)
                    subprocess.run([args.bezel, "render", font, "--text", args.text,
                                    "--font-size", str(px), "--margin", "16",
                                    "--foreground", fg, "--background", bg, "-o", bz_png]
                                   + extra, check=True)
                    hb_ink, hb_peak, hw, hh = ink(hb_png, polarity)
                    bz_ink, bz_peak, bw, bh = ink(bz_png, polarity)
                    if (hw, hh) != (bw, bh) and polarity == "dark":
                        print(f"# {os.path.basename(font)} {px} px: page sizes differ, "
                              f"bezel {bw}x{bh}, hb-view {hw}x{hh}", file=sys.stderr)
                    ratio = bz_ink / hb_ink
                    worst = max(worst, abs(ratio - 1.0))
                    print(f"{os.path.basename(font)}\t{px}\t{polarity}\t{bz_ink}\t{hb_ink}\t"
                          f"{ratio:.3f}\t{bz_peak}\t{hb_peak}")
                    reference.append((os.path.relpath(font, os.path.join(ROOT, "fonts-test")),
                                      px, polarity, hb_ink, hb_peak))
        if args.pictures:
            pictures(args, fonts[0], sizes, args.pictures, tmp)
    print(f"# worst |ratio - 1|: {worst:.3f}; bezel render options: "
          f"{' '.join(extra) or '(default)'}; {hb_version}")
    if args.reference:
        with open(args.reference, "w") as f:
            f.write("# hb-view's ink per page, the reference tests/text_weight_test.cpp holds\n"
                    "# bezel's text weight to. Made by tools/bench/text_weight.py --reference\n"
                    f"# with {hb_version}\n"
                    "# (gray antialiasing, unhinted): hb-view FONT --text TEXT --font-size PX\n"
                    "# --margin 16; dark: --foreground #000000 --background #FFFFFF, light: the\n"
                    "# reverse. ink: the sum of (255 - value) dark, of value light; peak: the\n"
                    "# darkest value dark, the brightest light.\n"
                    f"text\t{args.text}\n"
                    "# font (under fonts-test/)\tpx\tpolarity\tink\tpeak\n")
            for row in reference:
                f.write("\t".join(str(v) for v in row) + "\n")


if __name__ == "__main__":
    main()
