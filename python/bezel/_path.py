"""bezel.Path (outlines and SVG path data), bezel.fill (exact-area coverage) and
bezel.encode_png (bezel's PNG writer). Pixels, y down, as everywhere in bezel."""

from __future__ import annotations

from typing import List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _bezel
from . import _check

Point = Tuple[float, float]
Segment = Tuple[str, Tuple[Point, ...]]
Rect = Tuple[float, float, float, float]
Transform = Sequence[float]


class Path:
    """An immutable path of line, quadratic and cubic segments in closed or open contours.

    ``Path(d)`` (or ``Path.from_svg(d)``) parses SVG path data: every command of SVG 1.1,
    arcs become cubics within 0.001 units. A malformed ``d`` raises bezel.Error naming the
    byte offset ("path data offset 7: expected a number, found 'x'").
    """

    __slots__ = ("_core",)

    def __init__(self, data: str = "") -> None:
        if not isinstance(data, str):
            raise TypeError(f"Path: expected SVG path data (str), got {_check.type_name(data)}")
        self._core = _bezel.Path.from_svg(data)

    @classmethod
    def from_svg(cls, data: str) -> "Path":
        return cls(data)

    @classmethod
    def _wrap(cls, core: "_bezel.Path") -> "Path":
        p = cls.__new__(cls)
        p._core = core
        return p

    @property
    def svg(self) -> str:
        """SVG path data (absolute M L Q C Z) that parses back to exactly this path."""
        return self._core.svg(17)

    def to_svg(self, precision: int = 17) -> str:
        """SVG path data with `precision` significant digits (1..17; 17 round-trips exactly)."""
        return self._core.svg(_check.integer("precision", precision, 1, 17))

    def bounds(self, transform: Optional[Transform] = None) -> Optional[Rect]:
        """The tight box (x0, y0, x1, y1) of the path mapped by `transform` (curves' extrema
        included), or None for a path without segments."""
        return self._core.bounds(_check.transform(transform))

    @property
    def control_box(self) -> Optional[Rect]:
        """The box of every point, control points included (None without segments)."""
        return self._core.control_box()

    def transformed(self, transform: Transform) -> "Path":
        """A new path: every point mapped by (a, b, c, d, e, f)."""
        t = _check.transform(transform)
        if t is None:
            raise TypeError("transform: expected 6 numbers (a, b, c, d, e, f), got None")
        return Path._wrap(self._core.transformed(t))

    @property
    def segments(self) -> List[Segment]:
        """(kind, points) per segment, kind "line" (2 points), "quad" (3) or "cubic" (4); a
        closed contour ends with its closing line when its last point is not its start."""
        return self._core.segments()

    @property
    def contour_count(self) -> int:
        return self._core.contour_count()

    @property
    def signed_area(self) -> float:
        """Enclosed area, positive for contours clockwise on screen (y down)."""
        return self._core.signed_area()

    def __reduce__(self):
        return (Path, (self.svg,))   # SVG data at 17 digits reads back bit for bit

    def __len__(self) -> int:
        return self._core.segment_count()

    def __bool__(self) -> bool:
        return not self._core.is_empty()

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Path):
            return NotImplemented
        return self._core.equals(other._core)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        svg = self._core.svg(6)
        if len(svg) > 60:
            svg = svg[:57] + "..."
        return f"bezel.Path({svg!r})"


def _as_path(path: Union[Path, str]) -> Path:
    if isinstance(path, Path):
        return path
    if isinstance(path, str):
        return Path(path)
    raise TypeError(f"path: expected a bezel.Path or SVG path data (str), "
                    f"got {_check.type_name(path)}")


def fill(path: Union[Path, str], width: int, height: int, *,
         transform: Optional[Transform] = None, rule: str = "nonzero",
         tolerance: float = _check.LIMITS["default_raster_tolerance_px"],
         out: Optional[np.ndarray] = None) -> np.ndarray:
    """Exact-area anti-aliased coverage of `path` (or SVG path data) mapped by `transform`
    into a (height, width) uint8 array: each pixel is round(covered area × 255).

    rule: "nonzero" or "evenodd". tolerance: the largest distance, in pixels, between a curve
    and the lines it is flattened into (0.01 px keeps the error at the 8-bit rounding floor).
    out: a writable (height, width) uint8 array to fill instead of a new one (every pixel is
    written; rows may be strided, a row's pixels must be adjacent); it is returned.
    The GIL is released while the path is rasterized.
    """
    p = _as_path(path)
    w = _check.integer("width", width, 0, _check.LIMITS["max_bitmap_dim"])
    h = _check.integer("height", height, 0, _check.LIMITS["max_bitmap_dim"])
    rule = _check.choice("rule", rule, ("nonzero", "evenodd"))
    tol = _check.number("tolerance", tolerance, _check.LIMITS["min_flatten_tolerance_px"],
                        float("inf"))
    if tol == float("inf"):
        raise ValueError("tolerance: must be finite")
    if out is not None and not isinstance(out, np.ndarray):
        raise TypeError(f"out: expected a numpy array, got {_check.type_name(out)}")
    return _bezel.fill(p._core, w, h, _check.transform(transform), rule, tol, out)


def encode_png(array: np.ndarray, *, compression: str = "default") -> bytes:
    """PNG bytes of a uint8 image: (H, W) gray, (H, W, 3) RGB or (H, W, 4) RGBA (straight
    alpha), by bezel's writer. compression: "fast", "default" or "small" (every level stores
    the same pixels; they trade time for size). The GIL is released while encoding."""
    if not isinstance(array, np.ndarray):
        raise TypeError(f"array: expected a numpy array, got {_check.type_name(array)}")
    compression = _check.choice("compression", compression, ("default", "fast", "small"))
    return _bezel.encode_png(array, compression)

