"""Shared fixtures of the Python package's tests (tests/python/test_*.py), run by ctest's
Python.pytest (tests/CMakeLists.txt) with the build tree's package on PYTHONPATH.

Environment (set by ctest): BEZEL_FONTS_DIR (fonts-test/), BEZEL_CLI (the bezel binary of the
same build), BEZEL_C_LIBRARY (libbezel_c.so of the same build). Run by hand:
    PYTHONPATH=build/test/python /usr/bin/python3 -m pytest tests/python
(a sanitized build also needs ASAN_OPTIONS=detect_leaks=0 and LD_PRELOAD="$(c++
-print-file-name=libasan.so) $(c++ -print-file-name=libstdc++.so)": docs/python.md)."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FONTS = pathlib.Path(os.environ.get("BEZEL_FONTS_DIR", ROOT / "fonts-test"))


def font_path(relative: str) -> str:
    return str(FONTS / relative)


DEJAVU = font_path("dejavu-sans/DejaVuSans.ttf")
CANTARELL = font_path("cantarell/Cantarell-Regular.otf")
ARABIC = font_path("noto-arabic/NotoSansArabic-Regular.ttf")
CJK = font_path("noto-cjk/NotoSansCJKjp-Subset.otf")
COLR = font_path("colour/twemoji_smiley-glyf_colr_1.ttf")
VARIABLE = font_path("edge-cases/EdgeCasesVariable.ttf")


@pytest.fixture(scope="session")
def dejavu():
    import bezel
    return bezel.Font(DEJAVU, size=20)


@pytest.fixture(scope="session")
def cli():
    """Runs the bezel CLI of the same build: cli(args...) -> stdout bytes (raises on failure)."""
    path = os.environ.get("BEZEL_CLI")
    if not path or not os.path.exists(path):
        pytest.skip("BEZEL_CLI (the bezel binary of this build) is not set")

    def run(*args: str) -> bytes:
        done = subprocess.run([path, *args], capture_output=True, check=False)
        assert done.returncode == 0, done.stderr.decode(errors="replace")
        return done.stdout

    return run


def read_pgm(data: bytes):
    """A binary PGM (P5, 8-bit) as a (H, W) uint8 array."""
    import numpy as np
    fields = []
    pos = 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P5" and fields[3] == b"255"
    w, h = int(fields[1]), int(fields[2])
    pixels = data[pos + 1:pos + 1 + w * h]
    return np.frombuffer(pixels, dtype=np.uint8).reshape(h, w)
