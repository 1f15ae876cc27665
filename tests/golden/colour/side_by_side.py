#!/usr/bin/python3
"""The side-by-side picture of tests/golden/colour/README.md: a dozen colour glyphs at 128 px,
Chromium's reference on the top row, bezel's rendering below.

    tests/golden/colour/side_by_side.py [COLOUR_GOLDEN_TEST] [OUT.png]

COLOUR_GOLDEN_TEST is the built tests/colour_golden_test (default: the first of build/release,
build/dev, build/test that has one); bezel's cells come from it (BEZEL_COLOUR_GOLDEN_OUT), so the
picture shows exactly what the test compares. OUT defaults to tools/bezel/pictures/colour-glyphs.png.
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import make_goldens as mg

# (font stem, glyph) at 128 px, left to right: gradients with each extend mode, a sweep, a skewed
# gradient, composite and blend modes, the text colour at alpha 0.3, clipping, nested transforms,
# a multi-glyph COLRv1 picture, then the two bitmap formats.
GLYPHS = [
    ("test_glyphs-glyf_colr_1", "linear_gradient_extend_mode_reflect"),
    ("test_glyphs-glyf_colr_1", "radial_contained_gradient_extend_mode_repeat"),
    ("test_glyphs-glyf_colr_1", "radial_horizontal_gradient_extend_mode_reflect"),
    ("test_glyphs-glyf_colr_1", "sweep_0_360_reflect_narrow"),
    ("test_glyphs-glyf_colr_1", "gradient_p2_skewed"),
    ("test_glyphs-glyf_colr_1", "composite_HSL_HUE"),
    ("test_glyphs-glyf_colr_1", "foreground_color_radial_alpha_0.3"),
    ("test_glyphs-glyf_colr_1", "inset_clipped_radial_reflect"),
    ("test_glyphs-glyf_colr_1", "paint_glyph_nested_rotate_center_rotate_center"),
    ("test_glyphs-glyf_colr_1", "colored_circles_v1"),
    ("twemoji_smiley-sbix", "u1F60D"),
    ("NotoColorEmoji-subset", "u1F600"),
]
SIZE_PX = 128
GAP_PX = 4
BACKDROP = 160   # gray between the cells


def load(path):
    w, h, rgba = mg.decode_png_rgba(Path(path).read_bytes())
    return np.frombuffer(rgba, np.uint8).reshape(h, w, 4)[:, :, :3]


def main():
    root = mg.ROOT
    test = Path(sys.argv[1]) if len(sys.argv) > 1 else next(
        (p for p in (root / "build" / b / "tests" / "colour_golden_test"
                     for b in ("release", "dev", "test")) if p.exists()), None)
    if test is None or not test.exists():
        raise SystemExit("side_by_side: no colour_golden_test built (give its path)")
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else root / "tools/bezel/pictures/colour-glyphs.png"
    with tempfile.TemporaryDirectory() as bezel_dir:
        # The comparison's verdict does not matter here: a failing cell is still worth showing.
        subprocess.run([str(test), "--gtest_filter=ColourGolden.ColrV1*:ColourGolden.Bitmap*"],
                       env=dict(os.environ, BEZEL_COLOUR_GOLDEN_OUT=bezel_dir),
                       stdout=subprocess.DEVNULL, check=False)
        rows = [[], []]
        for stem, glyph in GLYPHS:
            name = "chromium/%s-%s-%d.png" % (stem, glyph, SIZE_PX)
            mine = Path(bezel_dir) / name
            if not mine.exists():
                raise SystemExit("side_by_side: bezel wrote no %s (did the test run?)" % name)
            rows[0].append(load(mg.HERE / name))
            rows[1].append(load(mine))
    h, w, _ = rows[0][0].shape
    picture = np.full((2 * h + 3 * GAP_PX, len(GLYPHS) * (w + GAP_PX) + GAP_PX, 3), BACKDROP,
                      np.uint8)
    for r, cells in enumerate(rows):
        for i, cell in enumerate(cells):
            y, x = GAP_PX + r * (h + GAP_PX), GAP_PX + i * (w + GAP_PX)
            picture[y:y + h, x:x + w] = cell
    mg.encode_png(out, picture.shape[1], picture.shape[0], 3, picture.tobytes())
    print("side_by_side: wrote %s" % out)


if __name__ == "__main__":
    main()
