"""bezel.dataset's parts on their own, without Dask: corpus reading, font lists, seeded sample
parameters, geometry, colour mixing, shard files and the manifest."""
import dataclasses
import io
import json
import math
import os
import tarfile

import numpy as np
import pytest

from bezel.dataset import corpus, fonts, manifest, params, render, shards

from dataset_helpers import CANTARELL, DEJAVU, FONTS


def config(**changes):
    base = params.RunConfig(fonts=(DEJAVU, CANTARELL), font_names=("DejaVuSans.ttf",
                            "Cantarell-Regular.otf"), sizes=(16, 24, 32), seed=7, count=10,
                            shard_size=4, margin=(0, 9), angle=5.0, background=(150, 255),
                            foreground=(0, 90), colour="gray", png_compression="default",
                            missing_glyphs="skip")
    return dataclasses.replace(base, **changes)


# --- corpus -------------------------------------------------------------------------------------

def test_corpus_lines_drop_crlf_bom_and_blank_lines(tmp_path):
    p = tmp_path / "c.txt"
    p.write_bytes(b"\xef\xbb\xbfone\r\n\n  \ntwo\nthree")
    c = corpus.read_corpus(str(p))
    assert c.texts == ("one", "two", "three")
    assert c.line_numbers == (1, 4, 5)
    assert c.skipped_blank == 2


def test_invalid_utf8_names_line_and_byte_offset(tmp_path):
    p = tmp_path / "c.txt"
    p.write_bytes(b"good\nalso good\nbad \xff here\n")
    with pytest.raises(corpus.CorpusError) as e:
        corpus.read_corpus(str(p))
    # "bad " starts at byte 15, so 0xff is byte 19 of the file.
    assert "line 3" in str(e.value) and "byte offset 19" in str(e.value) and str(p) in str(e.value)


def test_truncated_sequence_at_end_of_line_is_invalid(tmp_path):
    p = tmp_path / "c.txt"
    p.write_bytes(b"ok\n\xe2\x82\nok\n")  # the first two bytes of U+20AC
    with pytest.raises(corpus.CorpusError, match="line 2 at byte offset 3"):
        corpus.read_corpus(str(p))


def test_skip_invalid_counts_dropped_lines(tmp_path):
    p = tmp_path / "c.txt"
    p.write_bytes(b"a\n\xc3\x28\nb\n\xed\xa0\x80\nc\n")  # 2 invalid (one is a surrogate)
    c = corpus.read_corpus(str(p), skip_invalid=True)
    assert c.texts == ("a", "b", "c") and c.line_numbers == (1, 3, 5)
    assert c.skipped_invalid == 2


@pytest.mark.parametrize("data,what", [(b"", "is empty"), (b"\n  \n\t\n", "holds no sample")])
def test_corpus_without_samples_is_an_error(tmp_path, data, what):
    p = tmp_path / "c.txt"
    p.write_bytes(data)
    with pytest.raises(corpus.CorpusError, match=what):
        corpus.read_corpus(str(p))


def test_missing_corpus_and_folder_are_errors(tmp_path):
    with pytest.raises(corpus.CorpusError, match="cannot read corpus"):
        corpus.read_corpus(str(tmp_path / "nope.txt"))
    with pytest.raises(corpus.CorpusError, match="is a directory"):
        corpus.read_corpus(str(tmp_path))


def test_overlong_line_is_refused(tmp_path):
    p = tmp_path / "c.txt"
    p.write_bytes(b"x" * (corpus.MAX_LINE_BYTES + 1))
    with pytest.raises(corpus.CorpusError, match="line 1 is"):
        corpus.read_corpus(str(p))


# --- fonts ---------------------------------------------------------------------------------------

def test_font_folder_is_searched_recursively_in_sorted_order():
    found = fonts.find_fonts(os.path.join(FONTS, "noto-hebrew") + "," + FONTS + "/cantarell")
    assert [os.path.basename(p) for p in found] == ["NotoSansHebrew-Regular.ttf",
                                                     "Cantarell-Regular.otf"]
    everything = fonts.find_fonts(FONTS + "/colour")
    assert everything == sorted(everything) and len(everything) >= 5


def test_font_list_errors_name_the_input(tmp_path):
    with pytest.raises(fonts.FontListError, match="'/no/such.ttf' does not exist"):
        fonts.find_fonts("/no/such.ttf")
    (tmp_path / "readme.txt").write_text("no fonts here")
    with pytest.raises(fonts.FontListError, match="holds no font"):
        fonts.find_fonts(str(tmp_path))
    with pytest.raises(fonts.FontListError, match="listed twice"):
        fonts.find_fonts(f"{DEJAVU},{DEJAVU}")
    with pytest.raises(fonts.FontListError, match="empty item"):
        fonts.find_fonts(f"{DEJAVU},")


# --- sample parameters ---------------------------------------------------------------------------

def test_uniforms_are_blake2b_of_seed_and_index():
    # The documented stream (params.py): anyone can recompute a sample's numbers.
    import hashlib
    digest = hashlib.blake2b(b"7:42", digest_size=64, person=b"bezel.dataset").digest()
    u = params.uniforms(7, 42)
    assert len(u) == params.DRAWS
    assert u[0] == int.from_bytes(digest[:6], "big") / 2 ** 48
    assert u[9] == int.from_bytes(digest[54:60], "big") / 2 ** 48
    assert all(0 <= x < 1 for x in u)


def test_parameters_depend_only_on_seed_and_index():
    c = config()
    forward = [params.draw_params(c, i) for i in range(50)]
    backward = [params.draw_params(c, i) for i in reversed(range(50))][::-1]
    assert forward == backward
    assert forward != [params.draw_params(config(seed=8), i) for i in range(50)]


def test_parameters_stay_in_their_ranges_and_cover_them():
    c = config(count=2000)
    drawn = [params.draw_params(c, i) for i in range(2000)]
    assert {p.font for p in drawn} == {0, 1}
    assert {p.size for p in drawn} == {16, 24, 32}
    assert {p.margin for p in drawn} == set(range(0, 10))
    angles = [p.angle for p in drawn]
    assert min(angles) >= -5 and max(angles) <= 5 and min(angles) < -4.5 and max(angles) > 4.5
    assert all(round(a, params.ANGLE_DECIMALS) == a for a in angles)
    assert all(150 <= p.background[0] <= 255 and 0 <= p.foreground[0] <= 90 for p in drawn)
    assert all(len(p.background) == 1 for p in drawn)
    rgb = params.draw_params(config(colour="rgb"), 3)
    assert len(rgb.background) == 3 and len(rgb.foreground) == 3


def test_zero_angle_range_gives_unrotated_samples():
    assert {params.draw_params(config(angle=0.0), i).angle for i in range(100)} == {0.0}


def test_shard_ranges_cover_every_sample_once():
    c = config(count=10, shard_size=4)
    assert c.shard_count == 3
    assert [list(c.shard_range(s)) for s in range(3)] == [[0, 1, 2, 3], [4, 5, 6, 7], [8, 9]]


# --- geometry and colour --------------------------------------------------------------------------

def test_unrotated_layout_box_sits_at_the_margin():
    w, h, t, box, quad, ink = render.layout_geometry(100, 30, (1.5, 3.0, 98.0, 29.0), 0.0, 5)
    assert (w, h) == (110, 40)
    assert t == (1.0, -0.0, 0.0, 1.0, 5.0, 5.0)
    assert box == [5, 5, 105, 35] and ink == [6.5, 8.0, 103.0, 34.0]
    assert quad == [[5, 5], [105, 5], [105, 35], [5, 35]]


def test_ink_beyond_the_layout_box_widens_the_image():
    # An italic overhang left of the pen origin: the image grows so nothing is clipped.
    w, h, t, box, _, ink = render.layout_geometry(100, 30, (-2.25, 0.0, 100.0, 30.0), 0.0, 0)
    assert w == 103 and t[4] == 3.0 and box[0] == 3.0 and ink[0] == 0.75


def test_quarter_turn_is_exact_and_swaps_the_sides():
    w, h, t, box, quad, _ = render.layout_geometry(100, 30, None, 90.0, 2)
    assert (w, h) == (34, 104)
    assert t[:4] == (0.0, -1.0, 1.0, 0.0)
    # The text's top left corner goes to the bottom left: it reads upwards.
    assert quad[0] == [2.0, 102.0] and quad[1] == [2.0, 2.0]
    assert box == [2.0, 2.0, 32.0, 102.0]


def test_rotated_box_contains_the_rotated_quad():
    w, h, t, box, quad, _ = render.layout_geometry(200, 40, None, 7.5, 3)
    xs, ys = [p[0] for p in quad], [p[1] for p in quad]
    assert box == [min(xs), min(ys), max(xs), max(ys)]
    assert 0 <= box[0] and box[2] <= w and 0 <= box[1] and box[3] <= h
    side = math.dist(quad[0], quad[1])
    assert abs(side - 200) < 2e-3  # a rotation keeps lengths (labels are rounded to 1e-3)


def test_composite_mixes_by_rounded_coverage():
    k = np.arange(256, dtype=np.uint8)[None, :]
    for bg, fg in ((200, 30), (30, 200), (255, 0), (7, 7), (0, 255)):
        out = render.composite(k, (bg,), (fg,))
        assert out.dtype == np.uint8 and out.shape == (1, 256)
        # Reference: bg + (fg - bg) k / 255, rounded half away from bg, in exact integers.
        d = abs(fg - bg)
        ref = [bg + (1 if fg >= bg else -1) * ((d * v * 2 + 255) // 510) for v in range(256)]
        assert out[0].tolist() == ref
        assert out[0, 0] == bg and out[0, 255] == fg


def test_composite_rgb_mixes_each_channel():
    coverage = np.array([[0, 255], [128, 64]], dtype=np.uint8)
    out = render.composite(coverage, (255, 0, 10), (0, 255, 10))
    assert out.shape == (2, 2, 3) and out.dtype == np.uint8
    assert out[0, 0].tolist() == [255, 0, 10] and out[0, 1].tolist() == [0, 255, 10]
    assert out[1, 0].tolist() == [127, 128, 10]  # 255 * 128/255 = 128 either way


# --- shard files and manifest ----------------------------------------------------------------

def test_tar_is_deterministic_and_readable(tmp_path):
    members = [("000000001.png", b"abc"), ("000000002.png", b"")]
    data = shards.tar_bytes(members)
    assert data == shards.tar_bytes(members)
    p = tmp_path / "x.tar"
    p.write_bytes(data)
    with tarfile.open(p) as tar:
        assert [(m.name, m.size, m.mtime) for m in tar.getmembers()] == [
            ("000000001.png", 3, 0), ("000000002.png", 0, 0)]


def tarfile_reference(members):
    """What Python's tarfile writes for the members (shards.tar_bytes builds it directly)."""
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w", format=tarfile.USTAR_FORMAT) as tar:
        for name, data in members:
            info = tarfile.TarInfo(name)
            info.size, info.mtime, info.mode = len(data), 0, 0o644
            info.uid = info.gid = 0
            info.uname = info.gname = ""
            tar.addfile(info, io.BytesIO(data))
    return buf.getvalue()


@pytest.mark.parametrize("sizes", [[], [0], [1], [511], [512], [513], [3, 0, 10240, 9000],
                                   list(range(0, 12000, 997))])
def test_tar_bytes_equal_tarfiles(sizes):
    rng = np.random.default_rng(len(sizes))
    members = [(f"{i:09d}.png", rng.integers(0, 256, n, dtype=np.uint8).tobytes())
               for i, n in enumerate(sizes)]
    members.append(("x" * 100, b"longest name"))
    assert shards.tar_bytes(members) == tarfile_reference(members)
    with pytest.raises(ValueError, match="ustar"):
        shards.tar_bytes([("x" * 101, b"")])


def test_shard_is_done_only_with_its_label_file(tmp_path):
    shards.write_shard(str(tmp_path), 3, [("000000012.png", b"png")], [{"text": "é"}])
    assert shards.shard_done(str(tmp_path), 3) and not shards.shard_done(str(tmp_path), 2)
    assert sorted(os.listdir(tmp_path)) == ["shard-00003.jsonl", "shard-00003.tar"]
    assert (tmp_path / "shard-00003.jsonl").read_text(encoding="utf-8") == '{"text":"é"}\n'
    os.unlink(tmp_path / "shard-00003.jsonl")
    assert not shards.shard_done(str(tmp_path), 3)


def test_stale_temporaries_are_removed(tmp_path):
    (tmp_path / ".tmp-shard-00000.tar.abc").write_bytes(b"half")
    (tmp_path / "shard-00001.jsonl").write_bytes(b"")
    assert shards.remove_stale_temporaries(str(tmp_path)) == 1
    assert os.listdir(tmp_path) == ["shard-00001.jsonl"]


def test_manifest_resumes_same_run_and_refuses_another(tmp_path):
    out = str(tmp_path / "ds")
    m = manifest.manifest_dict(config(), "c0ffee", ["a", "b"], "bezel", "1.0", False)
    assert manifest.check_or_write(out, m) is False
    assert manifest.check_or_write(out, m) is True
    other = manifest.manifest_dict(config(seed=9), "c0ffee", ["a", "b"], "bezel", "1.0", False)
    with pytest.raises(manifest.ManifestError, match=r"differing: seed\)"):
        manifest.check_or_write(out, other)
    with open(os.path.join(out, "manifest.json")) as f:
        assert json.load(f)["seed"] == 7


def test_foreign_folder_is_not_written_into(tmp_path):
    (tmp_path / "thesis.tex").write_text("precious")
    m = manifest.manifest_dict(config(), "c0ffee", ["a", "b"], "bezel", "1.0", False)
    with pytest.raises(manifest.ManifestError, match="not a bezel dataset folder"):
        manifest.check_or_write(str(tmp_path), m)
    assert os.listdir(tmp_path) == ["thesis.tex"]


def test_second_run_on_the_same_folder_is_locked_out(tmp_path):
    with manifest.RunLock(str(tmp_path)):
        with pytest.raises(manifest.ManifestError, match="another run"):
            with manifest.RunLock(str(tmp_path)):
                pass


# --- progress -------------------------------------------------------------------------------------

def test_progress_off_a_terminal_is_plain_lines():
    import io
    from bezel.dataset.progress import Progress
    stream = io.StringIO()
    p = Progress(shards_total=3, shards_done=1, samples_total=10, samples_done=4, stream=stream)
    p.advance(4)
    p.advance(2)
    p.show(final=True)
    lines = stream.getvalue().splitlines()
    assert "\r" not in stream.getvalue() and "\x1b" not in stream.getvalue()
    assert lines[0].startswith("bezel.dataset: [") and "2/3 shards, 8/10 samples" in lines[0]
    assert "3/3 shards, 10/10 samples" in lines[-1] and "samples/s" in lines[-1]
    assert len(lines) == 2  # the second advance came within PLAIN_EVERY_S: no line of its own
