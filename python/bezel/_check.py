"""Argument checks shared by the public calls: a wrong type is a TypeError, a bad value a
ValueError, each naming the argument. Ranges come from the library's limits
(bezel/limits.hpp, exported by the extension as ``_bezel.limits``), stated there once."""

from __future__ import annotations

import functools
import math
import numbers
from typing import Any, Iterable, Optional, Sequence, Tuple, Union

from . import _bezel

LIMITS = _bezel.limits

Colour = Union[str, Tuple[int, int, int], Tuple[int, int, int, int]]


def type_name(value: Any) -> str:
    return type(value).__name__


def number(name: str, value: Any, lo: float, hi: float, *, lo_open: bool = False) -> float:
    """A real number in [lo, hi] ((lo, hi] with lo_open): not a bool, not NaN."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a number, got {type_name(value)}")
    v = float(value)
    low_ok = v > lo if lo_open else v >= lo
    if not (low_ok and v <= hi):  # NaN fails both
        opening = "(" if lo_open else "["
        raise ValueError(f"{name}: {value!r} is outside {opening}{lo:g}, {hi:g}]")
    return v


def integer(name: str, value: Any, lo: int, hi: int) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: expected an int, got {type_name(value)}")
    v = int(value)
    if not lo <= v <= hi:
        raise ValueError(f"{name}: {v} is outside {lo}..{hi}")
    return v


def flag(name: str, value: Any) -> bool:
    if not isinstance(value, bool):
        raise TypeError(f"{name}: expected True or False, got {type_name(value)}")
    return value


def choice(name: str, value: Any, choices: Sequence[str]) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a str, got {type_name(value)}")
    if value not in choices:
        listed = ", ".join(repr(c) for c in choices)
        raise ValueError(f"{name}: {value!r}: expected one of {listed}")
    return value


def optional_str(name: str, value: Any) -> Optional[str]:
    if value is None:
        return None
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a str or None, got {type_name(value)}")
    return value


# Pages are rendered in a few colours, each named on every call: parse each string once.
@functools.lru_cache(maxsize=256)
def _parsed_colour(text: str) -> Tuple[int, int, int, int]:
    return _bezel.parse_color(text)


def colour(name: str, value: Any) -> Tuple[int, int, int, int]:
    """A colour as bezel's CLI takes it ("#rrggbb", "#rrggbbaa", "#rgb", a CSS name,
    "transparent"; the library's parser) or an (r, g, b) / (r, g, b, a) tuple of ints 0..255."""
    if isinstance(value, str):
        try:
            return _parsed_colour(value)
        except ValueError as e:
            raise ValueError(f"{name}: {e}") from None
    if isinstance(value, (tuple, list)) and len(value) in (3, 4):
        channels = [integer(f"{name}[{k}]", c, 0, 255) for k, c in enumerate(value)]
        if len(channels) == 3:
            channels.append(255)
        return (channels[0], channels[1], channels[2], channels[3])
    raise TypeError(f"{name}: expected a colour string or an (r, g, b[, a]) tuple, "
                    f"got {type_name(value)}")


def text(name: str, value: Any) -> Union[str, bytes]:
    """Text to draw: str, or bytes of UTF-8 (the library checks it and names a bad byte)."""
    if isinstance(value, (bytes, bytearray, memoryview)):
        return bytes(value)
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected str or bytes, got {type_name(value)}")
    return value


def features(value: Any) -> str:
    """OpenType features in hb-view's syntax: "kern,-liga" or a sequence of such items."""
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple)) and all(isinstance(f, str) for f in value):
        return ",".join(value)
    raise TypeError(f"features: expected a str such as 'kern,-liga' or a list of str, "
                    f"got {type_name(value)}")


def transform(value: Any) -> Optional[Tuple[float, ...]]:
    """An affine map (a, b, c, d, e, f) as SVG's matrix(): x' = a·x + c·y + e, y' = b·x + d·y + f."""
    if value is None:
        return None
    # The common case first, without the per-entry ABC checks below (several µs a call, the
    # dataset renderer makes two a sample): a tuple of 6 finite floats is returned as it is.
    if (type(value) is tuple and len(value) == 6 and all(type(v) is float for v in value)
            and all(map(math.isfinite, value))):
        return value
    if isinstance(value, (str, bytes)) or not isinstance(value, Iterable):
        raise TypeError(f"transform: expected 6 numbers (a, b, c, d, e, f), got {type_name(value)}")
    entries = list(value)
    if len(entries) != 6:
        raise ValueError(f"transform: expected 6 numbers (a, b, c, d, e, f), got {len(entries)}")
    out = []
    for k, v in enumerate(entries):
        if isinstance(v, bool) or not isinstance(v, numbers.Real):
            raise TypeError(f"transform[{k}]: expected a number, got {type_name(v)}")
        if not math.isfinite(float(v)):
            raise ValueError(f"transform[{k}]: {v!r} is not finite")
        out.append(float(v))
    return tuple(out)


def custom_palette(value: Any) -> Optional[list]:
    """Palette entries to replace: {index: colour} or a list of colours (entry k for item k)."""
    if value is None:
        return None
    if isinstance(value, dict):
        items = list(value.items())
    elif isinstance(value, (list, tuple)):
        items = list(enumerate(value))
    else:
        raise TypeError(f"custom_palette: expected a dict {{index: colour}} or a list of colours, "
                        f"got {type_name(value)}")
    return [(integer("custom_palette index", i, 0, 0xFFFF), colour(f"custom_palette[{i}]", c))
            for i, c in items]
