"""bezel.Path, bezel.fill and bezel.encode_png: exact coverage, SVG round trips, caller arrays."""

import io

import numpy as np
import pytest

import bezel


def test_fill_of_a_square_is_exact():
    mask = bezel.fill("M2 2H8V8H2Z", 10, 10)
    assert mask.shape == (10, 10) and mask.dtype == np.uint8
    expected = np.zeros((10, 10), np.uint8)
    expected[2:8, 2:8] = 255
    assert np.array_equal(mask, expected)


def test_fill_of_a_half_pixel_offset_square_is_exact_area():
    mask = bezel.fill("M0.5 0.5H2.5V2.5H0.5Z", 3, 3)
    # Corners a quarter covered (63.75 -> 64), edges half (127.5 -> 128), the centre whole.
    assert mask.tolist() == [[64, 128, 64], [128, 255, 128], [64, 128, 64]]


def test_fill_of_a_circle_has_its_area():
    r = 40.0
    d = f"M {50 + r} 50 A {r} {r} 0 1 1 {50 - r} 50 A {r} {r} 0 1 1 {50 + r} 50 Z"
    mask = bezel.fill(d, 100, 100)
    assert mask.sum() / 255 == pytest.approx(np.pi * r * r, rel=1e-4)


def test_fill_rules():
    d = "M0 0H10V10H0Z M3 3H7V7H3Z"   # the inner square wound the same way
    assert bezel.fill(d, 10, 10)[5, 5] == 255
    assert bezel.fill(d, 10, 10, rule="evenodd")[5, 5] == 0


def test_fill_transform_is_svg_matrix():
    # matrix(2 0 0 2 1 1): the unit square at (1, 1) scaled to 2x2 at (3, 3).
    mask = bezel.fill("M1 1H2V2H1Z", 8, 8, transform=(2, 0, 0, 2, 1, 1))
    assert mask[3:5, 3:5].tolist() == [[255, 255], [255, 255]] and mask.sum() == 4 * 255


def test_fill_into_a_caller_array():
    out = np.full((6, 6), 7, np.uint8)
    same = bezel.fill("M1 1H3V3H1Z", 6, 6, out=out)
    assert same is out
    assert out[1:3, 1:3].min() == 255 and out.sum() == 4 * 255   # every pixel written


def test_fill_into_a_window_of_a_larger_array():
    atlas = np.full((20, 30), 9, np.uint8)
    window = atlas[5:15, 10:20]
    bezel.fill("M0 0H10V10H0Z", 10, 10, out=window)
    assert (atlas[5:15, 10:20] == 255).all()
    outside = atlas.copy()
    outside[5:15, 10:20] = 9
    assert (outside == 9).all()


def test_fill_into_bottom_up_rows():
    base = np.zeros((4, 4), np.uint8)
    flipped = base[::-1]
    bezel.fill("M0 0H4V1H0Z", 4, 4, out=flipped)   # the top row of the flipped view
    assert (base[3] == 255).all() and base[:3].sum() == 0


def test_fill_result_is_not_a_copy():
    mask = bezel.fill("M0 0H1V1Z", 4, 4)
    assert mask.flags.owndata   # numpy's own buffer, written by the rasterizer in place


def test_path_svg_round_trip_is_exact():
    d = "M0.1 0.2C0.3333333333333333 0 2 1e-7 3 3Q4 5 6 7L8 9Z"
    p = bezel.Path(d)
    assert bezel.Path(p.svg) == p
    assert len(p) == 4 and p.contour_count == 1
    kinds = [k for k, _ in p.segments]
    assert kinds == ["cubic", "quad", "line", "line"]   # the closing line included


def test_path_bounds_and_transform():
    p = bezel.Path("M0 0Q10 10 20 0")
    x0, y0, x1, y1 = p.bounds()
    assert (x0, y0, x1, y1) == pytest.approx((0, 0, 20, 5))   # the curve's extremum, not (10,10)
    assert p.control_box == pytest.approx((0, 0, 20, 10))
    assert p.bounds((1, 0, 0, 1, 5, -5)) == pytest.approx((5, -5, 25, 0))
    moved = p.transformed((2, 0, 0, 2, 0, 0))
    assert moved.bounds() == pytest.approx((0, 0, 40, 10))
    assert bezel.Path("").bounds() is None and not bezel.Path("")


def test_path_area_and_repr():
    p = bezel.Path("M0 0H4V3H0Z")
    assert p.signed_area == pytest.approx(12)
    assert "M0 0" in repr(p)


def test_bad_svg_names_the_offset():
    with pytest.raises(bezel.Error, match="offset 4"):
        bezel.Path("M0 0x")


@pytest.mark.parametrize("shape", [(5, 7), (5, 7, 3), (5, 7, 4)])
def test_encode_png_round_trips_through_pillow(shape):
    from PIL import Image
    rng = np.random.default_rng(37)
    array = rng.integers(0, 256, size=shape, dtype=np.uint8)
    for compression in ("fast", "default", "small"):
        png = bezel.encode_png(array, compression=compression)
        assert png[:8] == b"\x89PNG\r\n\x1a\n"
        back = np.asarray(Image.open(io.BytesIO(png)))
        assert np.array_equal(back, array)


def test_encode_png_takes_strided_arrays():
    from PIL import Image
    array = np.arange(64, dtype=np.uint8).reshape(8, 8)
    for view in (array.T, array[::2, ::3], array[::-1]):
        back = np.asarray(Image.open(io.BytesIO(bezel.encode_png(view))))
        assert np.array_equal(back, view)


def test_rendered_pages_encode_to_the_same_pixels(dejavu):
    from PIL import Image
    page = dejavu.render("PNG", size=30)
    assert np.array_equal(np.asarray(Image.open(io.BytesIO(bezel.encode_png(page)))), page)
