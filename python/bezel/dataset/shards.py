"""Shard files: DIR/shard-NNNNN.tar (the PNG images) and DIR/shard-NNNNN.jsonl (their labels).

The images go in a plain POSIX tar, the layout WebDataset reads: one member per sample named
after its global index ("000000042.png"), in sample order, so a shard streams sequentially and
any tar tool lists or extracts it. The tar is deterministic (mtime 0, owner 0, mode 0644,
ustar headers): the same samples always give the same bytes.

Both files are written atomically: into a temporary file in DIR, flushed to disk (fsync), then
renamed over the final name, and the folder is synced. The label file is renamed last and is the
shard's completion mark: a shard is finished if and only if its .jsonl exists, so an interrupted
run never leaves a shard that looks finished, and a rerun redoes any shard without one.
"""
from __future__ import annotations

import io
import json
import os
import tempfile

SHARD_PREFIX = "shard-"
TEMP_PREFIX = ".tmp-"

# The process's umask, read once: mkstemp creates files 0600, and a shard should get the mode any
# new file of the user gets (0644 under the usual umask 022).
_UMASK = os.umask(0o022)
os.umask(_UMASK)


def shard_stem(shard: int) -> str:
    return f"{SHARD_PREFIX}{shard:05d}"


def image_name(index: int) -> str:
    return f"{index:09d}.png"


def shard_done(out_dir: str, shard: int) -> bool:
    stem = os.path.join(out_dir, shard_stem(shard))
    return os.path.exists(stem + ".jsonl") and os.path.exists(stem + ".tar")


def fsync_dir(path: str) -> None:
    fd = os.open(path, os.O_RDONLY | os.O_DIRECTORY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def write_atomic(path: str, data: bytes) -> None:
    """Writes data to path so that path holds either its old content or all of data, never a
    part: a unique temporary file beside it (two attempts at the same shard never share one),
    fsync, rename, folder fsync."""
    folder = os.path.dirname(path) or "."
    fd, tmp = tempfile.mkstemp(prefix=TEMP_PREFIX + os.path.basename(path) + ".", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            os.fchmod(f.fileno(), 0o666 & ~_UMASK)
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    fsync_dir(folder)


_BLOCK = 512           # tar's block: headers and data padded to it
_RECORD = 20 * _BLOCK  # an archive is a whole number of records (tar's default blocking factor)
# The ustar header of a member, after its 100-byte name and before its size: mode 0644, owner
# and group 0 (8-byte octal fields ending in NUL); after the size: mtime 0, then the checksum
# field (8 spaces while the checksum is summed), type "0" (a regular file), an empty link name,
# "ustar\0" "00", empty owner and group names, empty device numbers (NUL: not a device file),
# an empty prefix.
_MODE_IDS = b"0000644\0" b"0000000\0" b"0000000\0"
_AFTER_SIZE = (b"00000000000\0", b"0" + bytes(100) + b"ustar\x0000" + bytes(64 + 16 + 155 + 12))


def tar_header(name: str, size: int) -> bytes:
    """The ustar header block of a regular file `name` (ASCII, at most 100 bytes) of `size`
    bytes, mtime 0, owner 0, mode 0644: what tarfile writes for that TarInfo, built directly
    (tarfile's own path, with its TarInfo copies, cost ~60 µs a member)."""
    raw = name.encode("ascii")
    if len(raw) > 100 or size >= 8 ** 11:
        raise ValueError(f"tar member {name!r} of {size} bytes does not fit a ustar header")
    head = raw + bytes(100 - len(raw)) + _MODE_IDS + b"%011o\0" % size + _AFTER_SIZE[0]
    tail = _AFTER_SIZE[1]
    # The checksum: the sum of the header's bytes, its own field counted as 8 spaces; written as
    # 6 octal digits, NUL and a space (as tarfile and GNU tar write it).
    chksum = sum(head) + 8 * 0x20 + sum(tail)
    return head + b"%06o\0 " % chksum + tail


def tar_bytes(members: list) -> bytes:
    """A deterministic ustar archive of (name, bytes) members, in order (byte for byte what
    tarfile writes for them with mtime 0, owner 0, mode 0644 and no owner names)."""
    parts = []
    total = 0
    for name, data in members:
        parts.append(tar_header(name, len(data)))
        parts.append(data)
        pad = -len(data) % _BLOCK
        parts.append(bytes(pad))
        total += _BLOCK + len(data) + pad
    # The end: two zero blocks, then zeros to a whole record.
    end = 2 * _BLOCK
    end += -(total + end) % _RECORD
    parts.append(bytes(end))
    return b"".join(parts)


def label_line(label: dict) -> str:
    """One JSONL line: keys in a fixed order, UTF-8 text as is (not \\u escapes), no spaces."""
    return json.dumps(label, ensure_ascii=False, separators=(",", ":")) + "\n"


def write_shard(out_dir: str, shard: int, images: list, labels: list) -> None:
    """Writes one finished shard: the tar of (name, png) images, then its labels (the mark)."""
    stem = os.path.join(out_dir, shard_stem(shard))
    write_atomic(stem + ".tar", tar_bytes(images))
    write_atomic(stem + ".jsonl", "".join(label_line(l) for l in labels).encode("utf-8"))


def remove_stale_temporaries(out_dir: str) -> int:
    """Deletes temporary files an interrupted run left in out_dir; returns how many."""
    removed = 0
    for name in os.listdir(out_dir):
        if name.startswith(TEMP_PREFIX):
            try:
                os.unlink(os.path.join(out_dir, name))
                removed += 1
            except FileNotFoundError:
                pass
    return removed
