"""The settings of a run and the parameters of each sample.

A sample's parameters are a pure function of (seed, sample index): sample i is the same whichever
worker draws it, in whichever order, and a rerun of one shard redraws exactly what the first
run drew. The generator is counter-based: the DRAWS uniform numbers of sample i are cut from
BLAKE2b-512 of "seed:i" (personalised "bezel.dataset"), UNIFORM_BITS bits each. Against a seeded
numpy Generator per sample it costs ~2 µs instead of ~35 µs (creating a Generator is the cost,
not drawing), and it reproduces in any language and any numpy version. The draws have a fixed
order (font, size, margin, angle, background, foreground), each one always drawn, so that no
setting shifts another; the manifest's FORMAT_VERSION changes whenever this order or a formula
changes.
"""
from __future__ import annotations

import dataclasses
import hashlib

# Bumped when the same arguments would no longer give the same bytes (draw order, formulas,
# label fields, shard layout): a resume across versions is refused.
FORMAT_VERSION = 1

# Largest margin, in pixels, on each side of the text box: a margin is padding around a line of
# text, and 1024 px of it is already more than a full line at the largest useful sizes.
MAX_MARGIN_PX = 1024
# Largest |angle| in degrees: any rotation is drawn exactly; past 180 the range repeats itself.
MAX_ANGLE_DEG = 180.0
# Uniform numbers drawn per sample, and the bits of each: 10 x 48 bits fit one 64-byte digest;
# 2^-48 granularity is far below any bias a choice among a few hundred values could show.
DRAWS = 10
UNIFORM_BITS = 48
PERSON = b"bezel.dataset"
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


def uniforms(seed: int, index: int) -> list:
    """DRAWS numbers in [0, 1), uniform and independent, a pure function of (seed, index)."""
    digest = hashlib.blake2b(f"{seed}:{index}".encode(), digest_size=64, person=PERSON).digest()
    width = UNIFORM_BITS // 8
    return [int.from_bytes(digest[k * width:(k + 1) * width], "big") / (1 << UNIFORM_BITS)
            for k in range(DRAWS)]


def draw_params(config: RunConfig, index: int) -> SampleParams:
    """The parameters of sample `index`, a pure function of (config, index).

    A choice among n values is floor(u n) of the next uniform u. In order: font, size, margin,
    angle, background (3 channels), foreground (3 channels); gray uses the first channel."""
    u = uniforms(config.seed, index)

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
