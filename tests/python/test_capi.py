"""The C API (lib/include/bezel/bezel.h) from Python through ctypes, as another language's
binding would call it: NULL handles, zero and negative sizes and strides too small return error
statuses with a message, never a crash. tests/capi_test.cpp covers the API in C."""

import ctypes
import os

import numpy as np
import pytest

from conftest import DEJAVU

OK, INVALID_ARGUMENT, OUT_OF_RANGE, FILE_ERROR, FONT_ERROR, BUFFER_TOO_SMALL = 0, 1, 2, 3, 4, 5

c_size = ctypes.c_size_t
c_ptr = ctypes.c_void_p
c_ptrdiff = ctypes.c_ssize_t


class Transform(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in "abcdef"]


@pytest.fixture(scope="module")
def capi():
    path = os.environ.get("BEZEL_C_LIBRARY")
    if not path or not os.path.exists(path):
        pytest.skip("BEZEL_C_LIBRARY (libbezel_c.so of this build) is not set")
    lib = ctypes.CDLL(path)
    sig = {
        "bezel_last_error": (ctypes.c_char_p, []),
        "bezel_font_open_file": (ctypes.c_int, [ctypes.c_char_p, c_ptr, ctypes.POINTER(c_ptr)]),
        "bezel_font_open_memory": (ctypes.c_int, [c_ptr, c_size, c_ptr, ctypes.POINTER(c_ptr)]),
        "bezel_font_destroy": (None, [c_ptr]),
        "bezel_glyph_rasterizer_create": (ctypes.c_int, [c_ptr, c_ptr, ctypes.POINTER(c_ptr)]),
        "bezel_glyph_rasterizer_destroy": (None, [c_ptr]),
        "bezel_glyph_rasterizer_last_error": (ctypes.c_char_p, [c_ptr]),
        "bezel_glyph_render": (ctypes.c_int, [c_ptr, ctypes.c_uint32, c_ptr, c_size, c_ptrdiff,
                                              c_ptr]),
        "bezel_path_from_svg": (ctypes.c_int, [ctypes.c_char_p, c_size, ctypes.POINTER(c_ptr)]),
        "bezel_path_destroy": (None, [c_ptr]),
        "bezel_rasterizer_create": (ctypes.c_int, [ctypes.POINTER(c_ptr)]),
        "bezel_rasterizer_destroy": (None, [c_ptr]),
        "bezel_rasterizer_last_error": (ctypes.c_char_p, [c_ptr]),
        "bezel_rasterizer_fill": (ctypes.c_int, [c_ptr, c_ptr, c_ptr, c_ptr, c_ptr, c_size,
                                                 ctypes.c_int, ctypes.c_int, c_ptrdiff]),
        "bezel_text_renderer_create": (ctypes.c_int, [c_ptr, c_size, ctypes.POINTER(c_ptr)]),
        "bezel_text_render": (ctypes.c_int, [c_ptr, ctypes.c_char_p, c_size, c_ptr, ctypes.c_int,
                                             c_ptr, c_size, c_ptrdiff, c_ptr]),
    }
    for name, (restype, argtypes) in sig.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = restype, argtypes
    return lib


def test_null_handles_are_invalid_arguments(capi):
    out = c_ptr()
    assert capi.bezel_font_open_file(None, None, ctypes.byref(out)) == INVALID_ARGUMENT
    assert capi.bezel_last_error()
    assert capi.bezel_font_open_file(DEJAVU.encode(), None, None) == INVALID_ARGUMENT
    assert capi.bezel_font_open_memory(None, 0, None, ctypes.byref(out)) == INVALID_ARGUMENT
    assert capi.bezel_glyph_rasterizer_create(None, None, ctypes.byref(out)) == INVALID_ARGUMENT
    assert capi.bezel_glyph_render(None, 1, None, 0, 0, None) == INVALID_ARGUMENT
    assert capi.bezel_rasterizer_fill(None, None, None, None, None, 0, 1, 1, 1) == INVALID_ARGUMENT
    assert capi.bezel_text_renderer_create(None, 0, ctypes.byref(out)) != OK
    assert capi.bezel_text_render(None, b"a", 1, None, 0, None, 0, 0, None) == INVALID_ARGUMENT
    assert capi.bezel_path_from_svg(None, 5, ctypes.byref(out)) == INVALID_ARGUMENT
    assert not out.value   # no handle was made by any of them


def test_missing_font_and_bad_svg_name_the_input(capi):
    out = c_ptr()
    assert capi.bezel_font_open_file(b"/nonexistent.ttf", None, ctypes.byref(out)) == FILE_ERROR
    assert b"/nonexistent.ttf" in capi.bezel_last_error()
    data = b"M0 0 x"
    assert capi.bezel_path_from_svg(data, len(data), ctypes.byref(out)) != OK
    assert b"offset" in capi.bezel_last_error()


def test_fill_sizes_and_strides(capi):
    raster, path = c_ptr(), c_ptr()
    assert capi.bezel_rasterizer_create(ctypes.byref(raster)) == OK
    d = b"M0 0H4V4H0Z"
    assert capi.bezel_path_from_svg(d, len(d), ctypes.byref(path)) == OK
    try:
        buf = np.zeros((4, 8), np.uint8)
        p = buf.ctypes.data_as(c_ptr)
        # A stride shorter than a row, a buffer smaller than the rows, negative sizes.
        assert capi.bezel_rasterizer_fill(raster, path, None, None, p, buf.size, 8, 4, 4) \
            == BUFFER_TOO_SMALL
        assert capi.bezel_rasterizer_fill(raster, path, None, None, p, 8, 8, 4, 8) \
            == BUFFER_TOO_SMALL
        assert capi.bezel_rasterizer_fill(raster, path, None, None, p, buf.size, -1, 4, 8) \
            == OUT_OF_RANGE
        assert capi.bezel_rasterizer_fill(raster, path, None, None, p, buf.size, 8, 99999, 8) \
            != OK
        assert capi.bezel_rasterizer_last_error(raster)
        assert not buf.any()   # nothing written by a refused call
        nan = Transform(float("nan"), 0, 0, 1, 0, 0)
        assert capi.bezel_rasterizer_fill(raster, path, ctypes.byref(nan), None, p, buf.size,
                                          8, 4, 8) != OK
        # Zero size: nothing to write, no buffer needed.
        assert capi.bezel_rasterizer_fill(raster, path, None, None, None, 0, 0, 0, 0) == OK
        assert capi.bezel_rasterizer_fill(raster, path, None, None, p, buf.size, 8, 4, 8) == OK
        assert buf[:, :4].min() == 255 and buf[:, 4:].max() == 0
    finally:
        capi.bezel_path_destroy(path)
        capi.bezel_rasterizer_destroy(raster)


def test_glyph_render_size_query_and_bad_stride(capi):
    font, glyphs = c_ptr(), c_ptr()
    assert capi.bezel_font_open_file(DEJAVU.encode(), None, ctypes.byref(font)) == OK
    try:
        assert capi.bezel_glyph_rasterizer_create(font, None, ctypes.byref(glyphs)) == OK
        buf = np.zeros(4096, np.uint8)
        p = buf.ctypes.data_as(c_ptr)
        assert capi.bezel_glyph_render(glyphs, 36, None, 0, 0, None) == BUFFER_TOO_SMALL
        assert capi.bezel_glyph_render(glyphs, 36, p, buf.size, -16, None) != OK
        assert capi.bezel_glyph_render(glyphs, 36, p, buf.size, 1, None) == BUFFER_TOO_SMALL
        assert capi.bezel_glyph_render(glyphs, 10**7, p, buf.size, 64, None) == FONT_ERROR
        assert capi.bezel_glyph_rasterizer_last_error(glyphs)
        assert capi.bezel_glyph_render(glyphs, 36, p, buf.size, 64, None) == OK
        assert buf.any()
    finally:
        capi.bezel_glyph_rasterizer_destroy(glyphs)
        capi.bezel_font_destroy(font)
