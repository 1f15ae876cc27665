"""The command line of python3 -m bezel.dataset: arguments, their checks, and the exit codes.

Every argument and input is checked before anything is written (exit 2 for a malformed value,
1 for an input that cannot be used: a corpus, a font or an output folder), so a bad run leaves
no folder, manifest or shard behind.
"""
from __future__ import annotations

import argparse
import math
import os
import re
import socket
import sys
import tempfile
import textwrap

from . import corpus as corpus_mod
from . import driver, fonts as fonts_mod, manifest as manifest_mod, shards as shards_mod
from .params import MAX_ANGLE_DEG, MAX_MARGIN_PX, RunConfig
from .render import BezelRenderer, library_limit

PROG = "python3 -m bezel.dataset"
# Most samples per shard: a worker holds a whole shard's PNGs in memory before writing it
# (100000 samples of a few KiB each is a few hundred MiB).
MAX_SHARD_SIZE = 100_000
# Most samples one run may make (the sample index is written with 9 digits in image names).
MAX_COUNT = 999_999_999
# Most worker processes a LocalCluster is started with: far past any one machine's cores; a
# larger number is a typo, not a machine.
MAX_WORKERS = 1024
# Largest seed: numpy's SeedSequence takes any non-negative integer; 2^63 keeps it a JSON integer
# every reader parses exactly.
MAX_SEED = (1 << 63) - 1

EPILOG = """\
output: DIR/shard-NNNNN.tar (PNG images named after the sample index) and DIR/shard-NNNNN.jsonl
(one label per line: image, index, line, text, font, size, angle, margin, background,
foreground, width, height, box, quad, ink_box), DIR/manifest.json (the run's parameters).
A rerun with the same arguments resumes, drawing only the shards without a .jsonl.
exit status: 0 done, 1 an input or the run failed (message names it), 2 bad arguments.
guide: docs/dataset.md"""


class UsageError(Exception):
    pass


class InputError(Exception):
    pass


def _number(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise UsageError(f"{what}: '{text}' is not a number") from None
    if not math.isfinite(value):
        raise UsageError(f"{what}: '{text}' is not a finite number")
    return value


def parse_sizes(text: str) -> tuple:
    """--sizes: comma-separated em sizes in pixels, each > 0 and at most the library's largest."""
    largest = float(library_limit("max_font_size_px"))
    sizes = []
    for item in text.split(","):
        size = _number(item.strip(), f"--sizes '{text}'") if item.strip() else None
        if size is None:
            raise UsageError(f"--sizes '{text}': empty item")
        if size <= 0 or size > largest:
            raise UsageError(f"--sizes '{text}': {item.strip()} px is outside (0, {largest:g}] "
                             f"(the largest em size bezel draws)")
        sizes.append(int(size) if size == int(size) else size)
    return tuple(sizes)


def parse_range(text: str, what: str, lo: int, hi: int) -> tuple:
    """LO or LO:HI, integers within [lo, hi], LO <= HI."""
    m = re.fullmatch(r"\s*(-?\d+)\s*(?::\s*(-?\d+)\s*)?", text)
    if not m:
        raise UsageError(f"{what} '{text}': expected an integer N or a range LO:HI")
    a = int(m.group(1))
    b = int(m.group(2)) if m.group(2) is not None else a
    if a > b:
        raise UsageError(f"{what} '{text}': {a} is above {b}")
    if a < lo or b > hi:
        raise UsageError(f"{what} '{text}': outside {lo}..{hi}")
    return a, b


def check_scheduler(address: str) -> str:
    """A Dask address: PROTOCOL://HOST:PORT (tcp, tls, ws, wss, ucx) or HOST:PORT (tcp)."""
    if not re.fullmatch(r"(?:(?:tcp|tls|ws|wss|ucx)://)?(\[[0-9a-fA-F:]+\]|[A-Za-z0-9.\-_]+):"
                        r"(\d{1,5})", address) or not 0 < int(address.rsplit(":", 1)[1]) < 65536:
        raise UsageError(f"--scheduler '{address}': not a Dask scheduler address "
                         f"(expected tcp://HOST:PORT, e.g. tcp://10.0.0.5:8786)")
    return address


def probe_scheduler(address: str, timeout: float) -> None:
    """Opens and closes a TCP connection to the scheduler before anything is written, so an
    unreachable address fails with no output folder made. (Other protocols are left to Dask.)"""
    m = re.fullmatch(r"(?:tcp://)?(\[[0-9a-fA-F:]+\]|[^:/]+):(\d+)", address)
    if not m:
        return
    host = m.group(1).strip("[]")
    try:
        socket.create_connection((host, int(m.group(2))), timeout=timeout).close()
    except OSError as e:
        raise InputError(f"cannot connect to the Dask scheduler at '{address}': "
                         f"{e.strerror or e}") from None


def check_output_folder(out: str) -> None:
    """The output folder must be a folder we can create files in (or be creatable): checked by
    creating and removing a probe file in it or in its nearest existing parent, because
    permission bits do not tell (root ignores them; read-only mounts)."""
    path = os.path.abspath(out)
    if os.path.exists(path) and not os.path.isdir(path):
        raise InputError(f"output folder '{out}' exists and is not a folder")
    probe_dir = path
    while not os.path.exists(probe_dir):
        parent = os.path.dirname(probe_dir)
        if parent == probe_dir:
            break
        probe_dir = parent
    if not os.path.isdir(probe_dir):
        raise InputError(f"output folder '{out}' cannot be created: '{probe_dir}' is not a folder")
    try:
        fd, probe = tempfile.mkstemp(prefix=".bezel-probe-", dir=probe_dir)
        os.close(fd)
        os.unlink(probe)
    except OSError as e:
        what = "is not writable" if probe_dir == path else f"cannot be created in '{probe_dir}'"
        raise InputError(f"output folder '{out}' {what}: {e.strerror or e}") from None


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG, formatter_class=argparse.RawDescriptionHelpFormatter, epilog=EPILOG,
        description=textwrap.fill(
            "Render a text corpus into a sharded, labelled image dataset with bezel, in "
            "parallel on Dask. Each sample's font, size, margin, angle and colours are drawn "
            "from a generator seeded by (--seed, sample index): the same arguments give the "
            "same bytes, whatever the number of workers.", width=78))
    p.add_argument("corpus", metavar="CORPUS",
                   help="UTF-8 text file, one sample per line (blank lines are skipped)")
    p.add_argument("--fonts", required=True, metavar="F[,F...]",
                   help="font files and/or folders (searched recursively for .ttf .otf .ttc "
                        ".otc, in sorted order); a sample's font is drawn uniformly from them")
    p.add_argument("-o", "--out", required=True, metavar="DIR",
                   help="output folder (created; resumed when it holds the same run)")
    p.add_argument("--sizes", default="16,24,32", metavar="S[,S...]",
                   help="em sizes in pixels, drawn uniformly (default: %(default)s)")
    p.add_argument("--seed", default="0", metavar="S",
                   help="seed of every sample's generator, an integer >= 0 (default: 0)")
    p.add_argument("--count", metavar="N",
                   help="number of samples (default: one per corpus line; more go round the "
                        "corpus again with new parameters, fewer take its first lines)")
    p.add_argument("--shard-size", default="1000", metavar="K",
                   help="samples per shard (default: %(default)s)")
    p.add_argument("--margin", default="4", metavar="LO[:HI]",
                   help="pixels around the text box on every side (default: %(default)s)")
    p.add_argument("--angle", default="0", metavar="A",
                   help="rotation in degrees, drawn uniformly from [-A, A] in steps of 0.01, "
                        "counter-clockwise positive; the outlines are rotated, not the image "
                        "(default: 0)")
    p.add_argument("--background", default="255", metavar="LO[:HI]",
                   help="background level 0-255 (default: %(default)s)")
    p.add_argument("--foreground", default="0", metavar="LO[:HI]",
                   help="text level 0-255 (default: %(default)s)")
    p.add_argument("--colour", "--color", dest="colour", choices=("gray", "rgb"), default="gray",
                   help="gray: 8-bit gray images, one level for text and one for background; "
                        "rgb: RGB images, each channel drawn from the ranges (default: gray)")
    p.add_argument("--png-compression", choices=("fast", "default", "small"), default="default",
                   help="bezel.encode_png's compression effort (default: default)")
    p.add_argument("--missing-glyphs", choices=("skip", "keep", "error"), default="skip",
                   help="when a sample's font lacks a character of its text: skip the sample "
                        "(not written; counted on stderr), keep it (drawn with the font's "
                        ".notdef box, which its label does not show), or stop with an error "
                        "(default: skip)")
    p.add_argument("--skip-invalid", action="store_true",
                   help="drop corpus lines that are not valid UTF-8 (counted on stderr) instead "
                        "of stopping with an error")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", metavar="N",
                       help="worker processes of the local Dask cluster, one thread each "
                            "(default: the number of CPUs this process may use)")
    where.add_argument("--scheduler", metavar="ADDR",
                       help="use the running Dask cluster at ADDR (tcp://HOST:PORT) instead; its "
                            "workers must import bezel and see DIR at the same path")
    p.add_argument("--connect-timeout", default=str(driver.DEFAULT_CONNECT_TIMEOUT_S),
                   metavar="SECONDS", help="how long to try reaching --scheduler (default: "
                                           "%(default)s)")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress report")
    return p


def _int(text: str, what: str, lo: int, hi: int) -> int:
    if not re.fullmatch(r"\s*\d+\s*", text or ""):
        raise UsageError(f"{what} '{text}': expected a whole number {lo}..{hi}")
    value = int(text)
    if not lo <= value <= hi:
        raise UsageError(f"{what} '{text}': outside {lo}..{hi}")
    return value


def settings(args) -> dict:
    """The checked values of the arguments that need no file (UsageError otherwise)."""
    s = {"sizes": parse_sizes(args.sizes), "seed": _int(args.seed, "--seed", 0, MAX_SEED),
         "shard_size": _int(args.shard_size, "--shard-size", 1, MAX_SHARD_SIZE),
         "count": None if args.count is None else _int(args.count, "--count", 1, MAX_COUNT),
         "margin": parse_range(args.margin, "--margin", 0, MAX_MARGIN_PX),
         "background": parse_range(args.background, "--background", 0, 255),
         "foreground": parse_range(args.foreground, "--foreground", 0, 255),
         "workers": None, "scheduler": None}
    angle = _number(args.angle, "--angle")
    if not 0 <= angle <= MAX_ANGLE_DEG:
        raise UsageError(f"--angle '{args.angle}': outside 0..{MAX_ANGLE_DEG:g} degrees "
                         f"(the largest turn either way)")
    s["angle"] = angle
    if args.scheduler is not None:
        s["scheduler"] = check_scheduler(args.scheduler)
    else:
        default = str(len(os.sched_getaffinity(0)))  # the CPUs this process may use
        s["workers"] = _int(args.workers if args.workers is not None else default, "--workers",
                            1, MAX_WORKERS)
    timeout = _number(args.connect_timeout, "--connect-timeout")
    if timeout <= 0:
        raise UsageError(f"--connect-timeout '{args.connect_timeout}': must be above 0 seconds")
    s["connect_timeout"] = timeout
    return s


def open_fonts(paths: list) -> None:
    """Opens every font once in the driver, so a file that is not a font fails before any
    output exists rather than in a worker halfway through."""
    import bezel
    for path in paths:
        try:
            bezel.Font(path)
        except (bezel.Error, ValueError, OSError) as e:
            raise InputError(f"font '{path}' cannot be used: {e}") from None


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    err = sys.stderr

    def fail(code: int, message: str) -> int:
        err.write(f"{PROG.split()[-1]}: error: {message}\n")
        if code == 2:
            err.write(f"(see {PROG} --help)\n")
        return code

    try:
        s = settings(args)
    except UsageError as e:
        return fail(2, str(e))
    try:
        font_paths = fonts_mod.find_fonts(args.fonts)
        check_output_folder(args.out)
        if s["scheduler"] is not None:
            probe_scheduler(s["scheduler"], s["connect_timeout"])
        corpus = corpus_mod.read_corpus(args.corpus, skip_invalid=args.skip_invalid)
        open_fonts(font_paths)
    except (fonts_mod.FontListError, corpus_mod.CorpusError, InputError) as e:
        return fail(1, str(e))
    if corpus.skipped_invalid:
        err.write(f"bezel.dataset: skipped {corpus.skipped_invalid} corpus line"
                  f"{'s' if corpus.skipped_invalid != 1 else ''} of invalid UTF-8 "
                  f"(--skip-invalid)\n")

    import bezel
    config = RunConfig(
        fonts=tuple(font_paths), font_names=tuple(os.path.basename(p) for p in font_paths),
        sizes=s["sizes"], seed=s["seed"],
        count=s["count"] if s["count"] is not None else len(corpus.texts),
        shard_size=s["shard_size"], margin=s["margin"], angle=s["angle"],
        background=s["background"], foreground=s["foreground"], colour=args.colour,
        png_compression=args.png_compression, missing_glyphs=args.missing_glyphs)
    renderer = BezelRenderer()
    manifest = manifest_mod.manifest_dict(
        config, corpus.sha256, [fonts_mod.file_sha256(p) for p in font_paths], renderer.name,
        bezel.__version__, args.skip_invalid)
    out = os.path.abspath(args.out)
    try:
        os.makedirs(out, exist_ok=True)
        with manifest_mod.RunLock(out):
            resumed = manifest_mod.check_or_write(out, manifest)
            shards_mod.remove_stale_temporaries(out)
            if resumed and not args.quiet:
                left = len(driver.pending_shards(out, config))
                err.write(f"bezel.dataset: resuming '{args.out}': {config.shard_count - left} of "
                          f"{config.shard_count} shards already done\n")
            stats = driver.run(out, config, corpus, renderer, workers=s["workers"],
                               scheduler=s["scheduler"], connect_timeout=s["connect_timeout"],
                               progress_enabled=not args.quiet)
    except manifest_mod.ManifestError as e:
        return fail(1, str(e))
    except driver.RunError as e:
        return fail(1, f"{e}; the finished shards are kept: rerun the same command to resume")
    except OSError as e:
        return fail(1, f"output folder '{args.out}': {e.strerror or e}")
    except KeyboardInterrupt:
        err.write("\nbezel.dataset: interrupted; the finished shards are kept: rerun the same "
                  "command to resume\n")
        return 130
    if not args.quiet:
        err.write(f"bezel.dataset: {stats['samples']} samples in {stats['shards']} shards, "
                  f"{stats['seconds']:.1f} s ({stats['samples_per_s']:.1f} samples/s); "
                  f"{stats['skipped_shards']} shards were already done\n")
        if stats["left_out"]:
            err.write(f"bezel.dataset: {stats['left_out']} samples left out: their font lacks a "
                      f"character of their text (--missing-glyphs skip)\n")
    return 0
