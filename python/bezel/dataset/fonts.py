"""Finding the fonts of a run: files named on the command line, or the fonts inside folders.

The list is reproducible: a folder contributes every font file below it (recursively) in sorted
order of their paths relative to the folder, and the arguments keep their order. A sample's font
is an index into this list, so the same arguments on another machine draw the same fonts.
"""
from __future__ import annotations

import hashlib
import os

# File name endings taken as fonts inside a folder (case-insensitive): TrueType and OpenType
# fonts and collections (face 0 of a collection is used). Files named explicitly may have any name.
FONT_SUFFIXES = (".ttf", ".otf", ".ttc", ".otc")


class FontListError(Exception):
    """A --fonts argument that names no usable font; the message names it."""


def find_fonts(spec: str) -> list:
    """The font paths of a comma-separated --fonts value, files and folders, in order.

    Raises FontListError for an empty item, a missing path, a folder without fonts, a font
    listed twice, or two fonts with the same file name (labels name fonts by file name).
    """
    paths = []
    for item in spec.split(","):
        if not item:
            raise FontListError(f"--fonts '{spec}' has an empty item")
        if os.path.isdir(item):
            found = []
            for root, dirs, files in os.walk(item):
                dirs.sort()
                for name in files:
                    if name.lower().endswith(FONT_SUFFIXES):
                        found.append(os.path.join(root, name))
            if not found:
                raise FontListError(f"font folder '{item}' holds no font "
                                    f"({', '.join(FONT_SUFFIXES)} files)")
            paths.extend(sorted(found, key=lambda p: os.path.relpath(p, item)))
        elif os.path.exists(item):
            if not os.access(item, os.R_OK):
                raise FontListError(f"font '{item}' is not readable")
            paths.append(item)
        else:
            raise FontListError(f"font '{item}' does not exist")
    seen_real, seen_names = {}, {}
    for p in paths:
        real = os.path.realpath(p)
        if real in seen_real:
            raise FontListError(f"font '{p}' is listed twice (also as '{seen_real[real]}')")
        seen_real[real] = p
        name = os.path.basename(p)
        if name in seen_names:
            raise FontListError(f"fonts '{seen_names[name]}' and '{p}' have the same file name; "
                                f"labels name a font by its file name, so it must be unique")
        seen_names[name] = p
    return [os.path.abspath(p) for p in paths]


def file_sha256(path: str) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()
