"""bezel.dataset's bezel renderer on its own (no Dask): rotation of the outlines, labels that
match the pixels, colours."""
import dataclasses

import numpy as np

from bezel.dataset import params, render

from dataset_helpers import CANTARELL, DEJAVU, decode_png

CONFIG = params.RunConfig(fonts=(DEJAVU, CANTARELL), font_names=("DejaVuSans.ttf",
                          "Cantarell-Regular.otf"), sizes=(24,), seed=0, count=1, shard_size=1,
                          margin=(3, 3), angle=0.0, background=(255, 255), foreground=(0, 0),
                          colour="gray", png_compression="default", missing_glyphs="skip")


def sample(**changes):
    base = params.SampleParams(index=0, font=0, size=24, margin=3, angle=0.0, background=(255,),
                               foreground=(0,))
    return dataclasses.replace(base, **changes)


def test_quarter_turn_is_the_unrotated_image_turned():
    r = render.BezelRenderer()
    flat, g0 = r.draw("Rotate me: gj", sample(), CONFIG)
    turned, g90 = r.draw("Rotate me: gj", sample(angle=90.0), CONFIG)
    # The outlines are turned, not the pixels; a quarter turn with whole-pixel offsets covers
    # the same areas, so the images agree up to the rounding of a coverage sum (1 level).
    expected = np.rot90(flat)
    assert turned.shape == expected.shape
    diff = np.abs(turned.astype(int) - expected.astype(int))
    assert diff.max() <= 1 and (diff == 0).mean() > 0.99
    assert (g90.width, g90.height) == (g0.height, g0.width)


def test_small_angle_keeps_the_ink_inside_its_labels():
    r = render.BezelRenderer()
    for angle in (-3.25, 2.5, 15.0):
        image, g = r.draw("Sphinx of black quartz", sample(angle=angle, font=1), CONFIG)
        ink = np.argwhere(image < 255)
        y0, x0 = ink.min(axis=0)
        y1, x1 = ink.max(axis=0) + 1
        bx0, by0, bx1, by1 = g.ink_box
        # Inked pixels lie within the ink box rounded out to whole pixels, and reach it.
        assert np.floor(bx0) <= x0 and x1 <= np.ceil(bx1)
        assert np.floor(by0) <= y0 and y1 <= np.ceil(by1)
        assert x0 <= bx0 + 1 and by1 - 1 <= y1
        # The margin is clear on every side.
        assert (image[:3] == 255).all() and (image[-3:] == 255).all()
        assert (image[:, :3] == 255).all() and (image[:, -3:] == 255).all()


def test_unrotated_layout_box_starts_at_the_margin():
    _, g = render.BezelRenderer().draw("Hello", sample(), CONFIG)
    assert g.box[:2] == [3.0, 3.0] and g.quad[0] == [3.0, 3.0]
    assert g.box[2] <= g.width - 3 and g.box[3] <= g.height - 3


def test_colours_are_the_drawn_levels():
    config = dataclasses.replace(CONFIG, colour="rgb")
    r = render.BezelRenderer()
    out = r.render("Colour", sample(background=(250, 240, 10), foreground=(20, 30, 200)), config)
    pixels = decode_png(out.png)
    assert pixels.shape == (out.geometry.height, out.geometry.width, 3)
    assert pixels[0, 0].tolist() == [250, 240, 10]
    # Fully covered pixels exist in a 24 px stem, and have exactly the foreground colour.
    assert ([20, 30, 200] == pixels.reshape(-1, 3)).all(axis=1).any()


def test_missing_glyph_policy():
    text = "abc \u0915"  # a Devanagari letter: neither test font has it
    r = render.BezelRenderer()
    assert r.draw(text, sample(), CONFIG) is None
    keep = dataclasses.replace(CONFIG, missing_glyphs="keep")
    image, _ = r.draw(text, sample(), keep)
    assert (image < 255).any()
    strict = dataclasses.replace(CONFIG, missing_glyphs="error")
    try:
        r.draw(text, sample(), strict)
    except render.SampleError as e:
        assert "\u0915" in str(e) or "U+0915" in str(e) or "glyph" in str(e)
    else:
        raise AssertionError("missing_glyphs='error' drew a sample its font cannot draw")
