"""Drawing one sample with bezel: the text's outlines, rotated exactly, filled and coloured.

Every sample, rotated or not, takes the same route: Font.text_path lays the text out as one
path (page pixels, y down), bezel.fill rasterizes that path through the sample's transform
(rotation about the page origin, then a translation into the image), and the coverage is mixed
into the background in numpy. One route keeps the geometry of the image and of
its label the same function of the angle everywhere, 0 included: the unrotated image is the
angle-0 member of the family, not a differently rounded one.

Geometry (image pixels, y down): the layout box is the page text_path reports, (0, 0) to
(width, height) before the transform. The image holds the rotated layout box and the rotated
ink, whichever reaches further, plus the margin on every side; the translation is whole pixels
so that an unrotated text sits on the pixel grid as render() places it.
"""
from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np

from .params import RunConfig, SampleParams

_worker_cache: dict = {}


def library_limit(name: str) -> float:
    """One of the library's named limits (bezel/limits.hpp), as the binding reports them."""
    from .._check import LIMITS
    return LIMITS[name]


def worker_cached(key, make):
    """A per-process cache: make() runs once per key in each worker process (fonts are opened
    once per process, not once per task). The dict lives in this importable module so that
    renderers shipped to workers by value (cloudpickle) share it too."""
    value = _worker_cache.get(key)
    if value is None:
        value = _worker_cache[key] = make()
    return value


class SampleError(Exception):
    """A sample that cannot be drawn; the driver names its index and corpus line."""


@dataclasses.dataclass
class Geometry:
    """A sample image's size and label boxes, image pixels, y down."""
    width: int
    height: int
    box: list        # [x0, y0, x1, y1]: axis-aligned box of the rotated layout box
    quad: list       # the layout box's corners, rotated: [[x, y] * 4], from its top left, clockwise
    ink_box: list    # [x0, y0, x1, y1] of the drawn outlines, or None when nothing is inked


@dataclasses.dataclass
class Rendered:
    png: bytes
    geometry: Geometry


def rotation(angle_deg: float) -> tuple:
    """(cos, sin) of a counter-clockwise turn on a y-down image: x' = c x + s y, y' = -s x + c y.
    Whole quarter turns are exact (no 6e-17 residue from math.cos)."""
    quarter = angle_deg / 90.0
    if quarter == int(quarter):
        return [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(quarter) % 4]
    t = math.radians(angle_deg)
    return math.cos(t), math.sin(t)


def layout_geometry(page_w, page_h, ink, angle_deg, margin):
    """The image size, the SVG-style transform (a, b, c, d, e, f) from page to image pixels and
    the label boxes of a page_w x page_h layout with ink bounds `ink` (page pixels, None when
    nothing is inked) turned by angle_deg and padded by margin pixels."""
    c, s = rotation(angle_deg)

    def turn(x, y):
        return c * x + s * y, -s * x + c * y

    corners = [turn(x, y) for x, y in ((0, 0), (page_w, 0), (page_w, page_h), (0, page_h))]
    xs = [p[0] for p in corners]
    ys = [p[1] for p in corners]
    reach_x, reach_y = list(xs), list(ys)
    if ink is not None:
        reach_x += [ink[0], ink[2]]
        reach_y += [ink[1], ink[3]]
    x0, y0 = math.floor(min(reach_x)), math.floor(min(reach_y))
    width = math.ceil(max(reach_x)) - x0 + 2 * margin
    height = math.ceil(max(reach_y)) - y0 + 2 * margin
    e, f = margin - x0, margin - y0
    quad = [[round(x + e, 3), round(y + f, 3)] for x, y in corners]
    box = [round(min(xs) + e, 3), round(min(ys) + f, 3), round(max(xs) + e, 3),
           round(max(ys) + f, 3)]
    ink_box = None if ink is None else [round(ink[0] + e, 3), round(ink[1] + f, 3),
                                        round(ink[2] + e, 3), round(ink[3] + f, 3)]
    return width, height, (c, -s, s, c, float(e), float(f)), box, quad, ink_box


def composite(coverage: np.ndarray, background: tuple, foreground: tuple) -> np.ndarray:
    """coverage (H, W) uint8 mixed into the colours, per channel
        out = bg + round((fg - bg) k / 255)   (k the coverage 0..255; halves away from bg),
    in the encoded (sRGB) values as Pillow and cairo mix: (H, W) gray or (H, W, 3) RGB uint8.
    In uint16, |fg - bg| k + 127 <= 255 * 255 + 127 < 2^16, so nothing overflows."""
    channels = []
    for bg, fg in zip(background, foreground):
        x = coverage.astype(np.uint16)
        x *= abs(fg - bg)
        x += 127
        x //= 255
        channels.append(bg + x if fg >= bg else bg - x)
    out = channels[0] if len(channels) == 1 else np.stack(channels, axis=-1)
    return out.astype(np.uint8)


class Renderer:
    """What the shard task needs of a renderer: draw() one sample into an image array and its
    geometry, encode() that image as PNG. Instances are shipped to the workers, so they hold no
    state; per-process resources go through worker_cached."""
    name = "?"

    def draw(self, text: str, params: SampleParams, config: RunConfig):
        """-> (image (H, W) or (H, W, 3) uint8, Geometry), or None for a sample left out
        (config.missing_glyphs "skip": its font lacks a character of its text)."""
        raise NotImplementedError

    def encode(self, image: np.ndarray, config: RunConfig) -> bytes:
        raise NotImplementedError

    def render(self, text: str, params: SampleParams, config: RunConfig):
        """-> Rendered, or None for a sample left out."""
        drawn = self.draw(text, params, config)
        if drawn is None:
            return None
        image, g = drawn
        return Rendered(png=self.encode(image, config), geometry=g)


class BezelRenderer(Renderer):
    """Draws samples with the bezel package (imported in the worker, where it runs)."""
    name = "bezel"

    def draw(self, text: str, params: SampleParams, config: RunConfig):
        import bezel
        font_path = config.fonts[params.font]
        font = worker_cached(("bezel", font_path), lambda: bezel.Font(font_path))
        try:
            with warnings.catch_warnings(record=True) as missing:
                warnings.simplefilter("always", bezel.MissingGlyphWarning)
                tp = font.text_path(text, size=params.size, margin=0,
                                    strict=config.missing_glyphs == "error")
            if missing and config.missing_glyphs == "skip":
                return None
            c, s = rotation(params.angle)
            # None when nothing is inked (a text of spaces or marks without outlines).
            ink = tp.path.bounds(transform=(c, -s, s, c, 0.0, 0.0))
            width, height, transform, box, quad, ink_box = layout_geometry(
                tp.width, tp.height, ink, params.angle, params.margin)
            # bezel.fill's largest target (kMaxBitmapDim): a sample that would need more (a
            # long line at a large size) is an error naming it, not a clipped image.
            largest = int(library_limit("max_bitmap_dim"))
            if width > largest or height > largest:
                raise SampleError(f"the image would be {width} x {height} px, more than "
                                  f"{largest} px on a side")
            coverage = bezel.fill(tp.path, width, height, transform=transform)
        except bezel.Error as e:
            raise SampleError(str(e)) from None
        image = composite(coverage, params.background, params.foreground)
        return image, Geometry(width, height, box, quad, ink_box)

    def encode(self, image: np.ndarray, config: RunConfig) -> bytes:
        import bezel
        return bezel.encode_png(image, compression=config.png_compression)
