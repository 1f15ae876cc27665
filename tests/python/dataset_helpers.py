"""Helpers of the bezel.dataset tests: running the command as a user does, and reading what it
wrote. (conftest.py belongs to the binding's tests; these are imported explicitly.)"""
from __future__ import annotations

import io
import json
import os
import subprocess
import tarfile

import bezel

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FONTS = os.path.join(ROOT, "fonts-test")
DEJAVU = os.path.join(FONTS, "dejavu-sans", "DejaVuSans.ttf")
CANTARELL = os.path.join(FONTS, "cantarell", "Cantarell-Regular.otf")
# Debian's interpreter, the one the package is built for (not a pyenv shim on PATH).
PYTHON = "/usr/bin/python3"
# A dataset run's subprocess gets this long before the test fails instead of hanging.
RUN_TIMEOUT_S = 300

CORPUS_LINES = [
    "The quick brown fox jumps over the lazy dog.",
    "Grüße aus Köln — 12,50 €",
    "fi fl ffi: ligatures",
    "",
    "Pack my box with five dozen liquor jugs",
    "0123456789 !?#%&*()[]{}",
    "   leading spaces",
    "A",
    "Sphinx of black quartz, judge my vow.",
]


def package_env(**extra) -> dict:
    """The environment of a subprocess that imports the same bezel package as this process
    (its folder first on PYTHONPATH), plus extra variables."""
    env = dict(os.environ)
    pkg_root = os.path.dirname(os.path.dirname(os.path.abspath(bezel.__file__)))
    env["PYTHONPATH"] = os.pathsep.join(
        [pkg_root] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    env.update(extra)
    return env


def run_dataset(args, *, env=None, timeout=RUN_TIMEOUT_S) -> subprocess.CompletedProcess:
    """Runs python3 -m bezel.dataset ARGS; returns the completed process (text output)."""
    return subprocess.run([PYTHON, "-m", "bezel.dataset", *map(str, args)],
                          env=env or package_env(), capture_output=True, text=True,
                          timeout=timeout)


def write_corpus(path, lines=CORPUS_LINES) -> str:
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return str(path)


def dataset_files(out_dir) -> dict:
    """{name: bytes} of a dataset folder's files (the lock file aside: it holds nothing)."""
    files = {}
    for name in sorted(os.listdir(out_dir)):
        if name == ".lock":
            continue
        with open(os.path.join(out_dir, name), "rb") as f:
            files[name] = f.read()
    return files


def read_labels(out_dir) -> list:
    labels = []
    for name in sorted(os.listdir(out_dir)):
        if name.endswith(".jsonl"):
            with open(os.path.join(out_dir, name), encoding="utf-8") as f:
                labels.extend(json.loads(line) for line in f)
    return labels


def read_images(out_dir) -> dict:
    """{member name: PNG bytes} of every shard tar in the folder."""
    images = {}
    for name in sorted(os.listdir(out_dir)):
        if name.endswith(".tar"):
            with tarfile.open(os.path.join(out_dir, name)) as tar:
                for member in tar.getmembers():
                    images[member.name] = tar.extractfile(member).read()
    return images


def decode_png(data: bytes):
    """The pixels of a PNG as a numpy array (Pillow decodes: an independent reader)."""
    import numpy as np
    from PIL import Image
    return np.asarray(Image.open(io.BytesIO(data)))
