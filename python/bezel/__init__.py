"""bezel: fonts and vector outlines to pixels, from Python.

    import bezel
    font = bezel.Font("DejaVuSans.ttf", size=24)
    page = font.render("Hello, world")             # (H, W) uint8 gray, or (H, W, 4) RGBA
    glyph = font.glyph("g")                         # bitmap and metrics
    outline = font.outline("g")                     # segments, SVG path data, bounds
    mask = bezel.fill("M2 2H8V8H2Z", 10, 10)        # exact-area coverage
    png = bezel.encode_png(page)                    # bezel's PNG writer
    PIL.Image.fromarray(page)                       # Pillow, without a copy of the pixels

A pybind11 extension (bezel._bezel) over bezel's C++ library; docs/python.md is the guide.
Pixels are y down. Calls that shape, rasterize or encode release the GIL.
"""

from . import _bezel
from ._font import Axis, Font, Glyph, Outline, TextPath
from ._path import Path, encode_png, fill

__version__: str = _bezel.version

# bezel's own errors (a file that is not a font, a layout too large, invalid UTF-8 in bytes):
# the message is the library's, naming the input. Arguments of the wrong type or out of range
# raise TypeError / ValueError before the library is called.
Error = _bezel.Error
Error.__module__ = "bezel"
# A character no font of the list has, drawn as the first font's .notdef box (strict=True makes
# it an Error instead).
MissingGlyphWarning = _bezel.MissingGlyphWarning
MissingGlyphWarning.__module__ = "bezel"

__all__ = [
    "Axis", "Error", "Font", "Glyph", "MissingGlyphWarning", "Outline", "Path", "TextPath",
    "encode_png", "fill", "__version__",
]
