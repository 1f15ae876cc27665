"""python3 -m bezel.dataset on bad input, run as a user runs it: exit 2 for a malformed argument,
1 for an input that cannot be used, one message naming it, and nothing written."""
import os

import pytest

from dataset_helpers import DEJAVU, FONTS, run_dataset, write_corpus


@pytest.fixture
def corpus(tmp_path):
    return write_corpus(tmp_path / "corpus.txt", ["one line", "another line"])


def check_refused(result, code, *fragments, out=None):
    assert result.returncode == code, result.stderr
    assert "Traceback" not in result.stderr, result.stderr
    for fragment in fragments:
        assert fragment in result.stderr, result.stderr
    if out is not None:
        assert not os.path.exists(out) or not [n for n in os.listdir(out) if n.startswith("shard")]


def test_help_documents_every_option():
    r = run_dataset(["--help"])
    assert r.returncode == 0
    for option in ("--fonts", "--out", "--sizes", "--seed", "--count", "--shard-size", "--margin",
                   "--angle", "--background", "--foreground", "--colour", "--png-compression",
                   "--skip-invalid", "--missing-glyphs", "--workers", "--scheduler",
                   "--connect-timeout", "--quiet"):
        assert option in r.stdout
    assert "docs/dataset.md" in r.stdout


@pytest.mark.parametrize("sizes,fragment", [
    ("0", "0 px is outside"), ("-3", "-3 px is outside"), ("abc", "'abc' is not a number"),
    ("1e9", "1e9 px is outside (0, 16384]"), ("16,,24", "empty item"), ("nan", "not a finite"),
])
def test_bad_sizes_are_usage_errors(tmp_path, corpus, sizes, fragment):
    out = tmp_path / "out"
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", out, "--sizes", sizes])
    check_refused(r, 2, f"--sizes '{sizes}'", fragment)
    assert not out.exists()


@pytest.mark.parametrize("args,fragment", [
    (["--workers", "0"], "--workers '0': outside 1..1024"),
    (["--workers", "two"], "--workers 'two'"),
    (["--shard-size", "0"], "--shard-size '0'"),
    (["--count", "-5"], "--count '-5'"),
    (["--seed", "-1"], "--seed '-1'"),
    (["--margin", "8:2"], "--margin '8:2': 8 is above 2"),
    (["--background", "0:300"], "--background '0:300': outside 0..255"),
    (["--angle", "181"], "--angle '181'"),
    (["--scheduler", "not an address"], "--scheduler 'not an address': not a Dask scheduler"),
    (["--scheduler", "tcp://host:99999"], "not a Dask scheduler address"),
    (["--workers", "2", "--scheduler", "tcp://h:1"], "not allowed with argument"),
])
def test_bad_arguments_are_usage_errors(tmp_path, corpus, args, fragment):
    out = tmp_path / "out"
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", out, *args])
    check_refused(r, 2, fragment)
    assert not out.exists()


def test_invalid_utf8_names_line_and_byte(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_bytes(b"fine\nbroken \xc3 line\n")
    out = tmp_path / "out"
    r = run_dataset([bad, "--fonts", DEJAVU, "--out", out])
    check_refused(r, 1, str(bad), "invalid UTF-8 on line 2 at byte offset 12", "--skip-invalid")
    assert not out.exists()


@pytest.mark.parametrize("data,fragment", [(b"", "is empty"), (b"\n\n", "holds no sample")])
def test_empty_corpus_is_refused(tmp_path, data, fragment):
    empty = tmp_path / "empty.txt"
    empty.write_bytes(data)
    out = tmp_path / "out"
    check_refused(run_dataset([empty, "--fonts", DEJAVU, "--out", out]), 1, fragment)
    assert not out.exists()


def test_missing_corpus_is_refused(tmp_path):
    out = tmp_path / "out"
    r = run_dataset([tmp_path / "nope.txt", "--fonts", DEJAVU, "--out", out])
    check_refused(r, 1, "cannot read corpus", "nope.txt")
    assert not out.exists()


def test_missing_font_and_fontless_folder_are_refused(tmp_path, corpus):
    out = tmp_path / "out"
    r = run_dataset([corpus, "--fonts", tmp_path / "Missing.ttf", "--out", out])
    check_refused(r, 1, "Missing.ttf' does not exist")
    r = run_dataset([corpus, "--fonts", os.path.join(FONTS, "cantarell") + "/LICENSE," + FONTS
                     + "/noto-cjk/README.md", "--out", out])
    check_refused(r, 1, "cannot be used")
    r = run_dataset([corpus, "--fonts", tmp_path, "--out", out])
    check_refused(r, 1, "holds no font")
    assert not out.exists()


def test_unwritable_output_folder_is_refused(tmp_path, corpus):
    blocker = tmp_path / "a-file"
    blocker.write_text("x")
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", blocker])
    check_refused(r, 1, "exists and is not a folder")
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", blocker / "sub"])
    check_refused(r, 1, "cannot be created")
    # /proc refuses new files even to root, for whom permission bits do not count.
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", "/proc/bezel-dataset-test"])
    check_refused(r, 1, "output folder '/proc/bezel-dataset-test'")
    assert not os.path.exists("/proc/bezel-dataset-test")


def test_unreachable_scheduler_is_a_clear_runtime_error(tmp_path, corpus):
    # Port 9 (discard) on loopback: nothing listens there, so the connection is refused.
    out = tmp_path / "out"
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", out, "--scheduler", "tcp://127.0.0.1:9",
                     "--connect-timeout", "1"])
    check_refused(r, 1, "cannot connect to the Dask scheduler at 'tcp://127.0.0.1:9'")
    assert not out.exists()
