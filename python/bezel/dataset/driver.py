"""Running the shards on Dask: one task per unfinished shard, on a LocalCluster of worker
processes (one thread each) or on an existing cluster.

Nothing here decides what a sample looks like: the tasks are pure functions of their arguments
(task.py), so the dataset is the same whatever the number of workers or the order the scheduler
picks. A worker that dies takes its running task with it; the scheduler reruns that task on
another (or the restarted) worker, up to distributed's allowed-failures (3 by default), and a
rerun writes the same bytes.

With an existing cluster every worker must import the same bezel and reach the output folder at
the same path (a shared file system): the workers write the shards themselves, so no image
passes through the scheduler.
"""
from __future__ import annotations

import contextlib
import logging
import time
import uuid

from .params import RunConfig
from .progress import Progress
from .shards import shard_done

# How long connecting to an existing scheduler may take, in seconds, by default (--connect-timeout).
DEFAULT_CONNECT_TIMEOUT_S = 10.0


class RunError(Exception):
    """The run could not finish; finished shards stay, a rerun resumes."""


class SchedulerError(RunError):
    """The scheduler could not be reached."""


def pending_shards(out_dir: str, config: RunConfig) -> list:
    return [s for s in range(config.shard_count) if not shard_done(out_dir, s)]


def shard_samples(config: RunConfig, corpus, shard: int) -> list:
    """[(index, corpus line, text)] of a shard: sample i takes corpus sample i mod n (a count
    beyond the corpus goes round it again, with new parameters)."""
    n = len(corpus.texts)
    return [(i, corpus.line_numbers[i % n], corpus.texts[i % n]) for i in config.shard_range(shard)]


@contextlib.contextmanager
def dask_client(workers: int | None, scheduler: str | None, connect_timeout: float):
    # distributed logs each lost worker and restart at WARNING: the run reports what matters.
    for name in ("distributed", "distributed.nanny", "distributed.scheduler", "distributed.worker"):
        logging.getLogger(name).setLevel(logging.ERROR)
    from distributed import Client, LocalCluster
    if scheduler is not None:
        try:
            client = Client(scheduler, timeout=connect_timeout)
        except (OSError, TimeoutError, ValueError) as e:
            raise SchedulerError(f"cannot connect to the Dask scheduler at '{scheduler}': "
                                 f"{e}") from None
        try:
            yield client
        finally:
            client.close()
        return
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=logging.ERROR)
    try:
        client = Client(cluster)
        try:
            yield client
        finally:
            client.close()
    finally:
        cluster.close()


def run_shards(client, out_dir: str, config: RunConfig, corpus, renderer, shards: list,
               progress: Progress) -> float:
    """Submits one task per shard and waits for all; returns (seconds the workers spent
    drawing, samples left out). On the first failure the rest is cancelled and RunError raised."""
    from distributed import as_completed
    from distributed.scheduler import KilledWorker
    from .task import render_shard

    # Keys unique to this run: a shared cluster may still remember another run's shard keys.
    run_id = uuid.uuid4().hex[:12]
    futures = [client.submit(render_shard, out_dir, s, shard_samples(config, corpus, s), config,
                             renderer, key=f"bezel-dataset-{run_id}-shard-{s:05d}", pure=False)
               for s in shards]
    busy = 0.0
    skipped = 0
    try:
        for future in as_completed(futures):
            try:
                _, count, left_out, seconds = future.result()
            except KilledWorker as e:
                raise RunError(f"shard {future.key.rsplit('-', 1)[1]}: its worker died on every "
                               f"attempt ({e})") from None
            except Exception as e:  # the task's own exception, re-raised here by distributed
                shard = future.key.rsplit("-", 1)[1]
                raise RunError(f"shard {shard}: {type(e).__name__}: {e}") from None
            busy += seconds
            skipped += left_out
            progress.advance(count + left_out)
    finally:
        client.cancel([f for f in futures if not f.done()])
    return busy, skipped


def run(out_dir: str, config: RunConfig, corpus, renderer, *, workers: int | None = None,
        scheduler: str | None = None, connect_timeout: float = DEFAULT_CONNECT_TIMEOUT_S,
        progress_enabled: bool = True, stream=None) -> dict:
    """Draws every unfinished shard of the dataset in out_dir (the manifest already written).
    Returns figures of the run: shards and samples drawn, wall seconds, samples/s."""
    shards = pending_shards(out_dir, config)
    pending = set(shards)
    done_samples = sum(len(config.shard_range(s)) for s in range(config.shard_count)
                       if s not in pending)
    progress = Progress(config.shard_count, config.shard_count - len(shards), config.count,
                        done_samples, stream=stream, enabled=progress_enabled)
    start = time.monotonic()
    busy, skipped = 0.0, 0
    if shards:
        with dask_client(workers, scheduler, connect_timeout) as client:
            progress.start = time.monotonic()  # the rate counts drawing, not cluster start-up
            busy, skipped = run_shards(client, out_dir, config, corpus, renderer, shards, progress)
    progress.show(final=True)
    wall = time.monotonic() - start
    drawn = config.count - done_samples
    return {"shards": len(shards), "skipped_shards": config.shard_count - len(shards),
            "samples": drawn, "left_out": skipped, "seconds": wall, "busy_seconds": busy,
            "samples_per_s": progress.rate()}
