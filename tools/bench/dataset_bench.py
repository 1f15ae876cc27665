#!/usr/bin/python3
"""Dataset rendering speed: bezel against Pillow on the same samples, through the same shard
writer and Dask driver, so that only drawing and PNG encoding differ.

Samples: the non-blank lines of the licence texts every Debian system has in
/usr/share/common-licenses (GPL, LGPL, GFDL, Apache, MPL, Artistic, CC0: about 3000
lines of English prose; --corpus FILE uses another text), DejaVu Sans and Cantarell
from fonts-test/, sizes 16/24/32 px, margins 2-8 px, angles within ±3°, gray 160-255 behind gray
0-96 text. Each sample's parameters come from bezel.dataset's seeded generator, so both renderers
draw the same text, font, size, angle, margin and colours.

The Pillow renderer is what a Pillow-based generator does (TextRecognitionDataGenerator,
SynthTIGER): ImageFont.truetype cached per font and size (once per worker process), ImageDraw.text
onto a background-filled canvas, Image.rotate(expand=True, bilinear) for the angle, PNG through
Pillow's encoder (zlib level 6). bezel: Font.text_path, bezel.fill through the rotation, the
colour table, bezel.encode_png.

Figures:
  render-only   one process, no Dask: samples drawn per second (draw) and drawn + encoded as PNG
                (draw+png), best of --reps passes over --render-count samples (and of --rounds
                rounds, which alternate the renderers); Pillow twice, with
                its default PNG level (6) and with level 1 ("pillow-z1", bezel's deflate effort
                on images this small).
  end-to-end    python3 -m bezel.dataset's driver on a LocalCluster of 1 and of 2 worker processes
                (one thread each): samples/s from the first task submitted to the last shard
                written (cluster start-up excluded), --count samples in shards of --shard-size,
                best of --rounds alternating runs.
The ratio bezel / Pillow of each figure is printed; "per core" is the 1-worker figure.

Usage: PYTHONPATH=<folder holding the bezel package> /usr/bin/python3 tools/bench/dataset_bench.py
         [--count N] [--render-count N] [--reps N] [--rounds N] [--workers 1,2] [--corpus FILE]
         [--profile bezel|pillow]
(docs/dataset.md#benchmark). --profile runs the render-only loop of one renderer under cProfile
and prints where the time goes.
"""
from __future__ import annotations

import argparse
import cProfile
import io
import os
import pstats
import shutil
import sys
import tempfile
import time

from bezel.dataset import corpus as corpus_mod, driver, params, render

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FONTS = [os.path.join(ROOT, "fonts-test", "dejavu-sans", "DejaVuSans.ttf"),
         os.path.join(ROOT, "fonts-test", "cantarell", "Cantarell-Regular.otf")]
LICENCES = ["GPL-1", "GPL-2", "GPL-3", "LGPL-2.1", "LGPL-3", "GFDL-1.3", "Apache-2.0", "MPL-1.1",
            "MPL-2.0", "Artistic", "CC0-1.0"]


class PillowRenderer(render.Renderer):
    """The same samples drawn the way Pillow-based generators draw them. compress_level: zlib's
    level for Pillow's PNG encoder (Pillow's default is 6; 1 is what bezel's "default" uses on
    images this small, so "pillow-z1" compares the drawing with equal deflate effort)."""

    def __init__(self, compress_level: int = 6):
        self.compress_level = compress_level
        self.name = "pillow" if compress_level == 6 else f"pillow-z{compress_level}"

    def draw(self, text, p, config):
        from PIL import Image, ImageDraw, ImageFont
        path = config.fonts[p.font]
        font = render.worker_cached(("pillow", path, p.size),
                                    lambda: ImageFont.truetype(path, p.size))
        mode = "L" if len(p.background) == 1 else "RGB"
        bg = p.background[0] if mode == "L" else tuple(p.background)
        fg = p.foreground[0] if mode == "L" else tuple(p.foreground)
        ascent, descent = font.getmetrics()
        # The canvas: ascender + descender high, as wide as the ink (one layout call, as
        # Pillow-based generators measure; bezel's page is the advance width, within a few px).
        x0, y0, x1, y1 = font.getbbox(text, anchor="la")
        left = max(0, -x0)
        width = x1 + left + 2 * p.margin
        height = max(ascent + descent, y1) + 2 * p.margin
        image = Image.new(mode, (width, height), bg)
        ImageDraw.Draw(image).text((p.margin + left, p.margin), text, font=font, fill=fg,
                                   anchor="la")
        if p.angle:
            image = image.rotate(p.angle, resample=Image.BILINEAR, expand=True, fillcolor=bg)
        g = render.Geometry(image.width, image.height, None, None, None)
        return image, g

    def encode(self, image, config):
        buf = io.BytesIO()
        image.save(buf, "PNG", compress_level=self.compress_level)
        return buf.getvalue()


def licence_corpus(folder: str) -> str:
    path = os.path.join(folder, "corpus.txt")
    with open(path, "w", encoding="utf-8") as out:
        for name in LICENCES:
            with open(os.path.join("/usr/share/common-licenses", name), encoding="utf-8") as f:
                for line in f:
                    if line.strip():
                        out.write(line.strip() + "\n")
    return path


def make_config(count: int, shard_size: int) -> params.RunConfig:
    names = tuple(os.path.basename(f) for f in FONTS)
    return params.RunConfig(fonts=tuple(FONTS), font_names=names,
                            sizes=(16, 24, 32), seed=1, count=count, shard_size=shard_size,
                            margin=(2, 8), angle=3.0, background=(160, 255), foreground=(0, 96),
                            colour="gray", png_compression="default", missing_glyphs="skip")


def render_only(renderer, corpus, config, n: int, reps: int) -> tuple:
    """Best-of-reps samples/s of draw, and of draw + encode, over the first n samples."""
    samples = [(corpus.texts[i % len(corpus.texts)], params.draw_params(config, i))
               for i in range(n)]
    for text, p in samples[:50]:  # warm the font caches
        renderer.render(text, p, config)
    best_draw = best_full = 0.0
    for _ in range(reps):
        start = time.perf_counter()
        for text, p in samples:
            renderer.draw(text, p, config)
        best_draw = max(best_draw, n / (time.perf_counter() - start))
        start = time.perf_counter()
        for text, p in samples:
            renderer.render(text, p, config)
        best_full = max(best_full, n / (time.perf_counter() - start))
    return best_draw, best_full


def end_to_end(renderer, corpus, config, workers: int, scratch: str) -> float:
    out = tempfile.mkdtemp(prefix=f"{renderer.name}-{workers}w-", dir=scratch)
    try:
        stats = driver.run(out, config, corpus, renderer, workers=workers,
                           progress_enabled=False)
    finally:
        shutil.rmtree(out)
    return stats["samples_per_s"]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=6000, help="samples of each end-to-end run")
    ap.add_argument("--shard-size", type=int, default=1000)
    ap.add_argument("--render-count", type=int, default=2000, help="samples of a render-only pass")
    ap.add_argument("--reps", type=int, default=2, help="render-only passes (best is kept)")
    ap.add_argument("--workers", default="1,2", help="worker counts of the end-to-end runs")
    ap.add_argument("--rounds", type=int, default=2,
                    help="rounds alternating the renderers (each figure: the best round)")
    ap.add_argument("--corpus", help="text file, one sample a line (default: the licences)")
    ap.add_argument("--profile", choices=("bezel", "pillow"))
    a = ap.parse_args()
    import PIL
    from PIL import features
    scratch = tempfile.mkdtemp(prefix="bezel-dataset-bench-")
    try:
        corpus = corpus_mod.read_corpus(a.corpus or licence_corpus(scratch))
        config = make_config(a.count, a.shard_size)
        renderers = [render.BezelRenderer(), PillowRenderer(), PillowRenderer(1)]
        if a.profile:
            r = renderers[0] if a.profile == "bezel" else renderers[1]
            prof = cProfile.Profile()
            prof.enable()
            render_only(r, corpus, config, a.render_count, 1)
            prof.disable()
            pstats.Stats(prof).sort_stats("tottime").print_stats(20)
            return 0
        import bezel
        print(f"corpus: {len(corpus.texts)} lines ({a.corpus or 'Debian licence texts'}); fonts: "
              f"{', '.join(config.font_names)}; sizes {config.sizes} px, angle ±{config.angle}°, "
              f"margin {config.margin} px; bezel {bezel.__version__}, Pillow {PIL.__version__} "
              f"(layout: {'raqm' if features.check('raqm') else 'basic'}), {os.cpu_count()} CPUs")
        # Rounds alternate the renderers and keep each one's best, so that a change of load on a
        # shared machine does not fall on one renderer only.
        rows = {r.name: (0.0, 0.0) for r in renderers}
        for _ in range(a.rounds):
            for r in renderers:
                draw, full = render_only(r, corpus, config, a.render_count, a.reps)
                rows[r.name] = (max(rows[r.name][0], draw), max(rows[r.name][1], full))
        for r in renderers:
            print(f"render-only {r.name:9}: draw {rows[r.name][0]:8.0f} /s, draw+png "
                  f"{rows[r.name][1]:8.0f} /s", flush=True)
        for col, what in ((0, "draw"), (1, "draw+png")):
            for peer in ("pillow", "pillow-z1"):
                print(f"render-only ratio bezel/{peer} ({what}): "
                      f"{rows['bezel'][col] / rows[peer][col]:.2f}")
        for workers in (int(w) for w in a.workers.split(",")):
            rates = {r.name: 0.0 for r in renderers[:2]}
            for _ in range(a.rounds):
                for r in renderers[:2]:
                    rates[r.name] = max(rates[r.name], end_to_end(r, corpus, config, workers,
                                                                  scratch))
            for r in renderers[:2]:
                print(f"end-to-end {workers} worker(s) {r.name:6}: {rates[r.name]:8.0f} samples/s",
                      flush=True)
            print(f"end-to-end {workers} worker(s) ratio bezel/pillow: "
                  f"{rates['bezel'] / rates['pillow']:.2f}")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
