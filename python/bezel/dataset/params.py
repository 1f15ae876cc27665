"""The settings of a run and the parameters of each sample.

A sample's parameters come from its own generator, numpy.random.default_rng([seed, index]), so
sample i is the same whichever worker draws it, in whichever order, and a rerun of one shard
redraws exactly what the first run drew. The draws happen in a fixed order (font, size, margin,
angle, background, foreground), each one always drawn, so that no setting shifts the stream of
another; the manifest's FORMAT_VERSION changes whenever this order or a formula changes. Any
numpy reproduces a sample's parameters: default_rng([seed, index]).random(10), then draw_params.
"""
from __future__ import annotations

import dataclasses

import numpy as np

# Bumped when the same arguments would no longer give the same bytes (draw order, formulas,
# label fields, shard layout): a resume across versions is refused.
FORMAT_VERSION = 1

# Largest margin, in pixels, on each side of the text box: a margin is padding around a line of
# text, and 1024 px of it is already more than a full line at the largest useful sizes.
MAX_MARGIN_PX = 1024
# Largest |angle| in degrees: any rotation is drawn exactly; past 180 the range repeats itself.
MAX_ANGLE_DEG = 180.0
# Uniform floats drawn per sample (see draw_params).
DRAWS = 10
# Angles are drawn in steps of 10^-ANGLE_DECIMALS degrees, so the angle in a label (printed to
# that many decimals) is exactly the angle drawn.
ANGLE_DECIMALS = 2


@dataclasses.dataclass(frozen=True)
class RunConfig:
    """Everything that decides the bytes of the dataset (and nothing that does not, such as the
    worker count): the manifest records it, and a resume must match it."""
    fonts: tuple            # absolute font paths, in draw order
    font_names: tuple       # their file names, as labels give them
    sizes: tuple            # em sizes in pixels
    seed: int
    count: int              # samples in the dataset
    shard_size: int         # samples per shard (the last shard may hold fewer)
    margin: tuple           # (lo, hi) pixels, inclusive
    angle: float            # angles are drawn from [-angle, angle] degrees
    background: tuple       # (lo, hi) gray levels 0..255, inclusive
    foreground: tuple       # (lo, hi) gray levels 0..255, inclusive
    colour: str             # "gray": one level each; "rgb": each channel drawn from the range
    png_compression: str    # bezel.encode_png's compression
    missing_glyphs: str     # a font lacking a character of the text: "skip" the sample (it is
                            # not written), "keep" it (.notdef boxes drawn), or "error"

    @property
    def shard_count(self) -> int:
        return (self.count + self.shard_size - 1) // self.shard_size

    def shard_range(self, shard: int) -> range:
        start = shard * self.shard_size
        return range(start, min(start + self.shard_size, self.count))


@dataclasses.dataclass(frozen=True)
class SampleParams:
    index: int
    font: int               # index into RunConfig.fonts
    size: float             # em size in pixels
    margin: int             # pixels on every side of the text box
    angle: float            # degrees, counter-clockwise on the image
    background: tuple       # (g,) or (r, g, b)
    foreground: tuple


def draw_params(config: RunConfig, index: int) -> SampleParams:
    """The parameters of sample `index`, a pure function of (config, index).

    One call draws DRAWS uniform floats u in [0, 1) (creating the generator costs far more
    than drawing, and a single call keeps the stream's layout fixed); a choice among n values
    is floor(u n), uniform up to the 2^-53 granularity of u. In order: font, size, margin,
    angle, background (3 channels), foreground (3 channels); gray uses the first channel."""
    u = np.random.default_rng([config.seed, index]).random(DRAWS).tolist()

    def pick(k: int, lo: int, hi: int) -> int:
        return lo + min(int(u[k] * (hi - lo + 1)), hi - lo)

    steps = int(round(config.angle * 10 ** ANGLE_DECIMALS))
    angle = pick(3, -steps, steps) / 10 ** ANGLE_DECIMALS
    channels = 3 if config.colour == "rgb" else 1
    return SampleParams(
        index=index, font=pick(0, 0, len(config.fonts) - 1),
        size=config.sizes[pick(1, 0, len(config.sizes) - 1)],
        margin=pick(2, config.margin[0], config.margin[1]),
        angle=angle + 0.0,  # + 0.0: no "-0.0" in labels
        background=tuple(pick(4 + c, *config.background) for c in range(channels)),
        foreground=tuple(pick(7 + c, *config.foreground) for c in range(channels)))
