"""One Dask task: draw and write one shard. It runs in a worker process.

A task is idempotent: its output is a pure function of its arguments (the samples' parameters
come from (seed, index), not from any state of the worker), and it writes only its own two files,
atomically. So a task rerun after its worker died, or run twice, leaves the same bytes.
"""
from __future__ import annotations

import os
import time

from .params import RunConfig, draw_params
from .render import SampleError
from .shards import image_name, write_shard

# TEST ONLY, never set in normal use: "SHARD:MARKER" makes the first attempt at shard SHARD kill
# its worker process (os._exit, as a crash or the OOM killer would) before writing anything. The
# first attempt is the one that creates the file MARKER (O_EXCL); later attempts find it and run
# normally. tests/python/test_dataset_dask.py uses it to check that a lost worker loses no shard.
FAULT_ENV = "BEZEL_DATASET_TEST_KILL_SHARD"


def _inject_fault(shard: int) -> None:
    spec = os.environ.get(FAULT_ENV)
    if not spec:
        return
    target, _, marker = spec.partition(":")
    if int(target) != shard or not marker:
        return
    try:
        os.close(os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644))
    except FileExistsError:
        return
    os._exit(70)


class ShardError(Exception):
    """A sample of the shard could not be drawn: names the sample and its corpus line."""


def label_of(params, text: str, line: int, font_name: str, g) -> dict:
    """The JSONL label of a sample (docs/dataset.md#labels): keys in this order."""
    colour = (lambda c: c[0] if len(c) == 1 else list(c))
    return {"image": image_name(params.index), "index": params.index, "line": line,
            "text": text, "font": font_name, "size": params.size, "angle": params.angle,
            "margin": params.margin, "background": colour(params.background),
            "foreground": colour(params.foreground), "width": g.width, "height": g.height,
            "box": g.box, "quad": g.quad, "ink_box": g.ink_box}


def render_shard(out_dir: str, shard: int, samples: list, config: RunConfig, renderer) -> tuple:
    """Draws samples [(index, corpus line, text), ...] and writes shard `shard` into out_dir.

    Returns (shard, samples written, samples left out, seconds spent drawing and encoding).
    Raises ShardError naming the first sample that cannot be drawn; nothing of the shard is
    written then.
    """
    _inject_fault(shard)
    images, labels = [], []
    busy = 0.0
    left_out = 0
    for index, line, text in samples:
        params = draw_params(config, index)
        start = time.perf_counter()
        try:
            r = renderer.render(text, params, config)
        except SampleError as e:
            font = config.font_names[params.font]
            raise ShardError(f"sample {index} (corpus line {line}, font '{font}', "
                             f"{params.size} px): {e}") from None
        busy += time.perf_counter() - start
        if r is None:
            left_out += 1
            continue
        images.append((image_name(index), r.png))
        labels.append(label_of(params, text, line, config.font_names[params.font], r.geometry))
    write_shard(out_dir, shard, images, labels)
    return shard, len(labels), left_out, busy
