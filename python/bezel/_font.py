"""bezel.Font: a font (with fallback fonts) that renders text and glyphs to numpy arrays.

Pixels, y down; sizes are em sizes in pixels. Every call that shapes or rasterizes releases
the GIL, and one Font may be used from many threads at once (each thread gets its own
renderer over the font's shared bytes)."""

from __future__ import annotations

import numbers
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _bezel
from . import _check
from ._path import Path, Rect, Segment

FontSource = Union[str, "os.PathLike[str]", bytes, bytearray, memoryview, "Font"]

HINTINGS = ("none", "light", "full", "auto")
MODES = ("auto", "gray", "rgba")
DIRECTIONS = ("auto", "ltr", "rtl", "ttb", "btt")
ALIGNS = ("start", "center", "end")


@dataclass(frozen=True)
class Axis:
    """A variation axis of a variable font, in the axis's user units (wght 100..900)."""
    tag: str
    name: str
    min: float
    default: float
    max: float


@dataclass(frozen=True, eq=False)
class Glyph:
    """One glyph drawn at a pen position (the bitmap's placement as FreeType's: its first
    row is `top` rows above the baseline, its first column `left` pixels right of the pen).

    image: (H, W) uint8 coverage, or (H, W, 4) uint8 straight RGBA for a colour glyph (or
    with mode="rgba"); an empty glyph (a space) is (0, 0)."""
    image: np.ndarray
    left: int
    top: int
    advance: float
    gid: int
    font: int
    color: bool

    def __repr__(self) -> str:
        return (f"bezel.Glyph(image={self.image.shape} {self.image.dtype}, left={self.left}, "
                f"top={self.top}, advance={self.advance:g}, gid={self.gid}, font={self.font}, "
                f"color={self.color})")


@dataclass(frozen=True, eq=False)
class Outline:
    """A glyph's outline at a size, pixels, y down, pen at the origin."""
    path: Path
    advance: float
    gid: int
    font: int

    def __repr__(self) -> str:
        return (f"bezel.Outline({len(self.path)} segments, bounds={self.bounds}, "
                f"advance={self.advance:g}, gid={self.gid}, font={self.font})")

    @property
    def segments(self) -> List[Segment]:
        return self.path.segments

    @property
    def svg(self) -> str:
        return self.path.svg

    @property
    def bounds(self) -> Optional[Rect]:
        """Tight (x0, y0, x1, y1) of the outline; None for an empty glyph."""
        return self.path.bounds()


@dataclass(frozen=True, eq=False)
class TextPath:
    """Every glyph outline of a laid-out text, placed where Font.render places it: page
    pixels, y down, on a page of width × height pixels (render()'s array shape)."""
    path: Path
    width: int
    height: int
    baseline: Optional[float]  # the first line's baseline y (vertical text: its column's x)

    def __repr__(self) -> str:
        return (f"bezel.TextPath({len(self.path)} segments, width={self.width}, "
                f"height={self.height}, baseline={self.baseline})")

    @property
    def ink_bounds(self) -> Optional[Rect]:
        return self.path.bounds()


def _source_of(name: str, value: Any) -> Tuple[Union[str, bytes], int, list]:
    """(path or bytes, face index, variations) of a Font argument or fallback entry."""
    if isinstance(value, Font):
        return value._sources[0]
    if isinstance(value, (bytes, bytearray, memoryview)):
        return (bytes(value), 0, [])
    if isinstance(value, (str, os.PathLike)):
        path = os.fspath(value)
        if isinstance(path, bytes):
            path = os.fsdecode(path)
        return (path, 0, [])
    raise TypeError(f"{name}: expected a font file path, the font's bytes or a bezel.Font, "
                    f"got {_check.type_name(value)}")


def _variations(value: Any) -> list:
    if value is None:
        return []
    if isinstance(value, Mapping):
        items = list(value.items())
    elif isinstance(value, (list, tuple)):
        items = list(value)
    else:
        raise TypeError(f"variations: expected a dict such as {{'wght': 700}}, "
                        f"got {_check.type_name(value)}")
    out = []
    for item in items:
        if not (isinstance(item, tuple) and len(item) == 2):
            raise TypeError("variations: expected (tag, value) pairs")
        tag, v = item
        if not isinstance(tag, str) or not 1 <= len(tag) <= 4 or not tag.isascii():
            raise ValueError(f"variations: axis tag {tag!r} is not 1 to 4 ASCII characters")
        v = _check.number(f"variations[{tag!r}]", v, -float("inf"), float("inf"))
        out.append((tag.ljust(4), v))  # OpenType pads short tags with spaces
    return out


def _size(name: str, value: Any) -> float:
    return _check.number(name, value, 0.0, _check.LIMITS["max_font_size_px"], lo_open=True)


def _glyph_key(value: Any) -> Tuple[int, bool]:
    """(code point, True) for a one-character str, (glyph id, False) for an int."""
    if isinstance(value, str):
        if len(value) != 1:
            raise ValueError(f"glyph: expected one character or a glyph id, got a str of "
                             f"length {len(value)}")
        return ord(value), True
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return _check.integer("glyph id", value, 0, 0xFFFFFFFF), False
    raise TypeError(f"glyph: expected one character (str) or a glyph id (int), "
                    f"got {_check.type_name(value)}")


class Font:
    """A font file (or its bytes) at a default size, with optional fallback fonts.

    Font(font, size=16.0, *, face_index=0, variations=None, hinting="none", fallback=(),
    system_fonts=False)

    font: a path (str or os.PathLike), the font's bytes (copied), or another Font.
    size: the default em size in pixels, (0, 16384]; every call may override it.
    variations: design coordinates of a variable font, e.g. {"wght": 700}.
    hinting: "none" (the design scaled exactly), "light", "full" or "auto" (FreeType's hinters).
    fallback: more fonts (paths, bytes or Fonts), in order; each grapheme cluster is drawn by
        the first font of the list that has it.
    system_fonts: also look in the system's fonts (fontconfig) for characters no listed font
        has. Off by default, so that output does not depend on the machine: characters no font
        has are drawn as the first font's .notdef box with a MissingGlyphWarning.

    Errors (a missing file, bytes that are not a font, an unknown axis) raise bezel.Error with
    bezel's message, which names the file.
    """

    def __init__(self, font: FontSource, size: float = 16.0, *, face_index: int = 0,
                 variations: Optional[Mapping[str, float]] = None, hinting: str = "none",
                 fallback: Sequence[FontSource] = (), system_fonts: bool = False) -> None:
        self._size = _size("size", size)
        self._hinting = _check.choice("hinting", hinting, HINTINGS)
        first = _source_of("font", font)
        face = _check.integer("face_index", face_index, 0, _check.LIMITS["max_face_index"])
        if isinstance(font, Font):
            face = face or first[1]
        sources = [(first[0], face, _variations(variations) or list(first[2]))]
        if isinstance(fallback, (str, bytes, os.PathLike, Font)):
            fallback = [fallback]
        if not isinstance(fallback, (list, tuple)):
            raise TypeError(f"fallback: expected a list of fonts, got {_check.type_name(fallback)}")
        for k, f in enumerate(fallback):
            sources.append(_source_of(f"fallback[{k}]", f))
        if len(sources) > _check.LIMITS["max_collection_fonts"]:
            raise ValueError(f"fallback: {len(sources)} fonts in all; at most "
                             f"{_check.LIMITS['max_collection_fonts']}")
        self._system_fonts = _check.flag("system_fonts", system_fonts)
        self._sources = sources
        self._core = _bezel.FontCore(sources, self._system_fonts)
        self._info: Dict[str, Any] = self._core.info()

    # Pickling (multiprocessing, Dask workers): a Font is rebuilt from its sources, the paths
    # or bytes it was made from, in the receiving process.
    def __reduce__(self):
        return (_rebuild_font, (self._sources, self._size, self._hinting, self._system_fonts))

    # --- Facts about the font ------------------------------------------------------------------
    @property
    def size(self) -> float:
        return self._size

    @property
    def hinting(self) -> str:
        return self._hinting

    @property
    def path(self) -> Optional[str]:
        """The file the font was read from; None for a font from bytes."""
        return self._info["file"]

    @property
    def family(self) -> str:
        return self._info["family"]

    @property
    def style(self) -> str:
        return self._info["style"]

    @property
    def face_index(self) -> int:
        return self._info["face_index"]

    @property
    def face_count(self) -> int:
        return self._info["face_count"]

    @property
    def glyph_count(self) -> int:
        return self._info["glyph_count"]

    @property
    def units_per_em(self) -> int:
        return self._info["units_per_em"]

    @property
    def has_color(self) -> bool:
        """The font has colour glyphs (COLR, CBDT or sbix)."""
        return self._info["has_color"]

    @property
    def axes(self) -> List[Axis]:
        return [Axis(*a) for a in self._info["axes"]]

    @property
    def fonts(self) -> List[str]:
        """The names of the font list: the font, then its fallbacks ("<bytes>" for bytes)."""
        return list(self._info["fonts"])

    # Face-wide metrics in pixels at the Font's size (unhinted: the font's units scaled by
    # size / units_per_em, so they scale linearly with the size).
    @property
    def ascender_px(self) -> float:
        """Distance from the baseline up to the ascender line, pixels (> 0)."""
        return self._info["ascender"] * self._size / self._info["units_per_em"]

    @property
    def descender_px(self) -> float:
        """Distance from the baseline down to the descender line, pixels (> 0)."""
        return -self._info["descender"] * self._size / self._info["units_per_em"]

    @property
    def line_height_px(self) -> float:
        """Baseline to baseline at line_height=1: ascender + descender + line gap, pixels."""
        i = self._info
        return (i["ascender"] - i["descender"] + i["line_gap"]) * self._size / i["units_per_em"]

    def __repr__(self) -> str:
        where = self.path if self.path is not None else "<bytes>"
        return f"bezel.Font({where!r}, size={self._size:g})"

    # --- Text ----------------------------------------------------------------------------------
    def _layout_options(self, size, width, margin, line_height, align, direction, features,
                        script, language, slant, hinting, strict) -> Dict[str, Any]:
        dim = float(_check.LIMITS["max_image_dim"])
        slant_max = _check.LIMITS["max_synthetic_slant"]
        return {
            "size": self._size if size is None else _size("size", size),
            "width": _check.number("width", width, 0.0, dim),
            "margin": _check.number("margin", margin, 0.0, dim),
            "line_height": _check.number("line_height", line_height, 0.0, float("inf")),
            "align": _check.choice("align", align, ALIGNS),
            "direction": _check.choice("direction", direction, DIRECTIONS),
            "features": _check.features(features),
            "script": _check.optional_str("script", script),
            "language": _check.optional_str("language", language),
            "slant": _check.number("slant", slant, -slant_max, slant_max),
            "hinting": None if hinting is None else _check.choice("hinting", hinting, HINTINGS),
            "strict": _check.flag("strict", strict),
        }

    def render(self, text: Union[str, bytes], *, size: Optional[float] = None,
               width: float = 0, margin: float = 0, line_height: float = 1.0,
               align: str = "start", direction: str = "auto",
               features: Union[str, Sequence[str]] = "", script: Optional[str] = None,
               language: Optional[str] = None, foreground: _check.Colour = "black",
               background: _check.Colour = "white", slant: float = 0, bold: float = 0,
               color: bool = True, palette: int = 0,
               custom_palette: Union[None, Mapping[int, _check.Colour],
                                     Sequence[_check.Colour]] = None,
               rendering: str = "perceptual", gamma: Optional[float] = None,
               contrast: Optional[float] = None, lcd: Optional[str] = None,
               hinting: Optional[str] = None, strict: bool = False,
               mode: str = "auto") -> np.ndarray:
        """Shapes, lays out and draws `text` onto a page sized to it, as `bezel render` does
        (its options in snake_case; `margin` defaults to 0 here, 16 there).

        Returns a (H, W) uint8 array of sRGB gray for gray text on a gray opaque page, else
        (H, W, 4) uint8 straight RGBA (colours, transparency, colour glyphs, lcd). mode="gray"
        or "rgba" asks for one form (gray needs opaque gray colours and no lcd).

        width: wrap lines at this many pixels (0: only the text's newlines). line_height: a
        multiple of the font's. align: start, center, end. direction: auto, ltr, rtl, ttb, btt.
        features: hb-view syntax, "kern,-liga,+smcp". foreground/background: "#rrggbb[aa]",
        "#rgb", a CSS colour name, "transparent" or an (r, g, b[, a]) tuple. slant: synthetic
        oblique (-1..1); bold: synthetic bold, a fraction of the em (0..0.25). color: draw colour
        glyphs in colour; palette / custom_palette: CPAL palette and entries to replace.
        rendering: "perceptual" (text weight as hb-view's, tuned by gamma 1..3 and contrast
        0..1) or "linear". lcd: "rgb" or "bgr" subpixel text. strict: a character no font has
        is a bezel.Error instead of a MissingGlyphWarning and the .notdef box.
        """
        options = self._layout_options(size, width, margin, line_height, align, direction,
                                       features, script, language, slant, hinting, strict)
        options.update(self._colour_options(foreground, color, palette, custom_palette))
        options["background"] = _check.colour("background", background)
        options["bold"] = _check.number("bold", bold, 0.0, _check.LIMITS["max_synthetic_bold"])
        options["rendering"] = _check.choice("rendering", rendering, ("perceptual", "linear"))
        if rendering == "linear" and (gamma is not None or contrast is not None):
            raise ValueError("gamma and contrast tune rendering='perceptual'; rendering='linear' "
                             "mixes exact coverage")
        if gamma is not None:
            options["gamma"] = _check.number("gamma", gamma, _check.LIMITS["min_text_gamma"],
                                             _check.LIMITS["max_text_gamma"])
        if contrast is not None:
            options["contrast"] = _check.number("contrast", contrast, 0.0,
                                                _check.LIMITS["max_text_contrast"])
        if lcd is not None:
            options["lcd"] = _check.choice("lcd", lcd, ("rgb", "bgr"))
        mode = _check.choice("mode", mode, MODES)
        return self._core.render(_check.text("text", text), options, mode, self._size,
                                 self._hinting)

    def text_path(self, text: Union[str, bytes], *, size: Optional[float] = None,
                  width: float = 0, margin: float = 0, line_height: float = 1.0,
                  align: str = "start", direction: str = "auto",
                  features: Union[str, Sequence[str]] = "", script: Optional[str] = None,
                  language: Optional[str] = None, slant: float = 0,
                  hinting: Optional[str] = None, strict: bool = False) -> TextPath:
        """The outlines of `text` laid out as render() lays it out (same options), as one
        bezel.Path in page pixels, with the page size and the first baseline: one C++ call,
        for filling the text with bezel.fill under any transform (a rotation, a perspective-free
        warp). Colour glyphs contribute their outlines. Synthetic bold has no outline and is
        not offered here."""
        options = self._layout_options(size, width, margin, line_height, align, direction,
                                       features, script, language, slant, hinting, strict)
        core, w, h, baseline = self._core.text_path(_check.text("text", text), options,
                                                    self._size, self._hinting)
        return TextPath(Path._wrap(core), w, h, baseline)

    # --- Glyphs --------------------------------------------------------------------------------
    def _colour_options(self, foreground, color, palette, custom_palette) -> Dict[str, Any]:
        return {
            "foreground": _check.colour("foreground", foreground),
            "color": _check.flag("color", color),
            "palette": _check.integer("palette", palette, 0, 0xFFFF),
            "custom_palette": _check.custom_palette(custom_palette),
        }

    def glyph(self, glyph: Union[str, int], *, size: Optional[float] = None,
              hinting: Optional[str] = None, slant: float = 0, bold: float = 0,
              offset: Tuple[float, float] = (0.0, 0.0), color: bool = True, palette: int = 0,
              custom_palette: Union[None, Mapping[int, _check.Colour],
                                    Sequence[_check.Colour]] = None,
              foreground: _check.Colour = "black", strict: bool = False,
              mode: str = "auto") -> Glyph:
        """One glyph's bitmap: `glyph` a character (drawn by the first font of the list that
        has it) or a glyph id of the first font. offset: the pen's subpixel position (x, y) in
        pixels. A colour glyph is (H, W, 4) straight RGBA; mode="gray" gives its alpha,
        mode="rgba" any glyph as coverage × foreground."""
        key, by_char = _glyph_key(glyph)
        limit = _check.LIMITS["max_glyph_offset_px"]
        if not (isinstance(offset, (tuple, list)) and len(offset) == 2):
            raise TypeError("offset: expected an (x, y) pair of numbers")
        options = self._colour_options(foreground, color, palette, custom_palette)
        options.update({
            "size": self._size if size is None else _size("size", size),
            "hinting": None if hinting is None else _check.choice("hinting", hinting, HINTINGS),
            "slant": _check.number("slant", slant, -_check.LIMITS["max_synthetic_slant"],
                                   _check.LIMITS["max_synthetic_slant"]),
            "bold": _check.number("bold", bold, 0.0, _check.LIMITS["max_synthetic_bold"]),
            "offset_x": _check.number("offset[0]", offset[0], -limit, limit),
            "offset_y": _check.number("offset[1]", offset[1], -limit, limit),
            "strict": _check.flag("strict", strict),
        })
        mode = _check.choice("mode", mode, MODES)
        image, left, top, advance, gid, font, is_colour = self._core.glyph(
            key, by_char, options, mode, self._size, self._hinting)
        return Glyph(image, left, top, advance, gid, font, is_colour)

    def outline(self, glyph: Union[str, int], *, size: Optional[float] = None,
                hinting: Optional[str] = None) -> Outline:
        """A glyph's outline (a character, or a glyph id of the first font) in pixels at
        `size`, y down, pen at the origin: segments, SVG path data, bounds."""
        key, by_char = _glyph_key(glyph)
        s = self._size if size is None else _size("size", size)
        h = self._hinting if hinting is None else _check.choice("hinting", hinting, HINTINGS)
        core, gid, font, advance = self._core.outline(key, by_char, s, h)
        return Outline(Path._wrap(core), advance, gid, font)


def _rebuild_font(sources: list, size: float, hinting: str, system_fonts: bool) -> Font:
    """A pickled Font: its checked sources (path or bytes, face index, variations) reopened."""
    font = Font.__new__(Font)
    font._size, font._hinting, font._system_fonts = size, hinting, system_fonts
    font._sources = sources
    font._core = _bezel.FontCore(sources, system_fonts)
    font._info = font._core.info()
    return font
