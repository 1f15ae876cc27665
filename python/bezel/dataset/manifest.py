"""DIR/manifest.json: the parameters a dataset was made with, so that a rerun resumes only the
same dataset.

It records every setting that decides the bytes of the output (RunConfig), the SHA-256 of the
corpus and of each font (a file edited in place is a different dataset), the format version and
bezel's version. It does not record what only decides the speed (workers, scheduler) or where
the inputs are (the corpus and fonts may move: their contents are what counts). A rerun
whose manifest differs is refused, naming the settings that differ.
"""
from __future__ import annotations

import dataclasses
import fcntl
import json
import os

from .params import FORMAT_VERSION, RunConfig
from .shards import write_atomic

MANIFEST_NAME = "manifest.json"
LOCK_NAME = ".lock"


class ManifestError(Exception):
    """The output folder holds another dataset (or something else); the message says what."""


def manifest_dict(config: RunConfig, corpus_sha256: str, font_sha256: list, renderer: str,
                  library_version: str, skip_invalid: bool) -> dict:
    d = {"format_version": FORMAT_VERSION, "renderer": renderer,
         "library_version": library_version, "corpus_sha256": corpus_sha256,
         "skip_invalid": skip_invalid}
    for field in dataclasses.fields(config):
        if field.name == "fonts":
            continue  # where the fonts are does not matter; what they hold does (font_sha256)
        value = getattr(config, field.name)
        d[field.name] = list(value) if isinstance(value, tuple) else value
    d["font_sha256"] = list(font_sha256)
    d["shard_count"] = config.shard_count
    return d


def check_or_write(out_dir: str, manifest: dict) -> bool:
    """Writes the manifest into out_dir (created if missing), or checks an existing one.

    Returns True when resuming (a matching manifest existed). Raises ManifestError when the
    manifest differs (naming the differing keys) or when out_dir holds files but no manifest.
    OSError (cannot create or write) propagates for the caller to report.
    """
    path = os.path.join(out_dir, MANIFEST_NAME)
    # JSON round trip: tuples become lists, so the comparison sees what the file holds.
    manifest = json.loads(json.dumps(manifest))
    if os.path.exists(path):
        try:
            with open(path, encoding="utf-8") as f:
                old = json.load(f)
        except (OSError, ValueError) as e:
            raise ManifestError(f"cannot read the manifest '{path}': {e}") from None
        if old != manifest:
            keys = sorted(k for k in set(old) | set(manifest) if old.get(k) != manifest.get(k))
            raise ManifestError(
                f"'{out_dir}' holds a dataset made with other parameters (differing: "
                f"{', '.join(keys)}); use another --out folder, or the arguments of that run "
                f"(see {path})")
        return True
    if os.path.isdir(out_dir):
        others = [n for n in os.listdir(out_dir) if n != LOCK_NAME]
        if others:
            raise ManifestError(f"'{out_dir}' is not empty and holds no {MANIFEST_NAME}: not a "
                                f"bezel dataset folder, refusing to write into it")
    os.makedirs(out_dir, exist_ok=True)
    write_atomic(path, (json.dumps(manifest, indent=1, ensure_ascii=False) + "\n").encode("utf-8"))
    return False


class RunLock:
    """An exclusive lock on the output folder (flock on DIR/.lock) for the driver's lifetime:
    two runs writing one folder would remove each other's temporary files."""

    def __init__(self, out_dir: str):
        self.path = os.path.join(out_dir, LOCK_NAME)
        self.fd = None

    def __enter__(self):
        self.fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(self.fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(self.fd)
            self.fd = None
            raise ManifestError(f"another run is writing '{os.path.dirname(self.path)}'") from None
        return self

    def __exit__(self, *exc):
        os.close(self.fd)
        self.fd = None
        return False
