"""python3 -m bezel.dataset end to end on Dask: the same seed gives the same bytes with one
worker and with two, a rerun resumes only missing shards, a changed argument is refused, and a
worker killed mid-run loses no shard.

Cluster start-ups cost seconds (more under ASan), so the runs are few and shared: one reference
run on a one-worker LocalCluster (the command's own), and one two-worker cluster started here
that the other runs reach through --scheduler."""
import logging
import os
import shutil

import pytest

from dataset_helpers import (CANTARELL, DEJAVU, decode_png, dataset_files, package_env,
                             read_images, read_labels, run_dataset, write_corpus)

# tornado (under distributed) warns about its own event loop use; nothing of ours.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

COUNT = 14        # the corpus has 8 samples: the last 6 go round it again
SHARD_SIZE = 4    # 4 shards, the last one short


def args(corpus, out, *extra):
    return [corpus, "--fonts", f"{DEJAVU},{CANTARELL}", "--out", out, "--sizes", "12,20",
            "--count", COUNT, "--shard-size", SHARD_SIZE, "--seed", 11, "--margin", "1:6",
            "--angle", "4", "--background", "170:255", "--foreground", "0:80", *extra]


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    return write_corpus(tmp_path_factory.mktemp("corpus") / "corpus.txt")


@pytest.fixture(scope="module")
def reference(corpus, tmp_path_factory):
    """The dataset made by one worker process (the command's own LocalCluster)."""
    out = tmp_path_factory.mktemp("one-worker") / "ds"
    r = run_dataset(args(corpus, out, "--workers", 1))
    assert r.returncode == 0, r.stderr
    return out


@pytest.fixture(scope="module")
def scheduler():
    from distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=logging.ERROR)
    client = Client(cluster)
    client.wait_for_workers(2)
    yield cluster.scheduler_address
    client.close()
    cluster.close()


@pytest.fixture(scope="module")
def two_workers(corpus, scheduler, tmp_path_factory):
    out = tmp_path_factory.mktemp("two-workers") / "ds"
    r = run_dataset(args(corpus, out, "--scheduler", scheduler))
    assert r.returncode == 0, r.stderr
    return out


def test_one_and_two_workers_write_the_same_bytes(reference, two_workers):
    one, two = dataset_files(reference), dataset_files(two_workers)
    assert sorted(one) == ["manifest.json"] + [f"shard-{s:05d}.{e}" for s in range(4)
                                               for e in ("jsonl", "tar")]
    assert one == two


def test_labels_describe_their_images(reference):
    labels = read_labels(reference)
    images = read_images(reference)
    assert [l["index"] for l in labels] == list(range(COUNT))
    assert sorted(images) == sorted(l["image"] for l in labels)
    texts = [l["text"] for l in labels]
    assert texts[:8] == texts[8:] + texts[6:8]  # the corpus, then round again
    assert {l["font"] for l in labels} == {"DejaVuSans.ttf", "Cantarell-Regular.otf"}
    for l in labels:
        pixels = decode_png(images[l["image"]])
        assert pixels.shape == (l["height"], l["width"])  # gray
        assert -4 <= l["angle"] <= 4 and 1 <= l["margin"] <= 6 and l["size"] in (12, 20)
        # The margin is background all round, and the ink stays inside the image.
        m = l["margin"]
        border = [pixels[:m].ravel(), pixels[-m:].ravel(), pixels[:, :m].ravel(),
                  pixels[:, -m:].ravel()]
        assert all((b == l["background"]).all() for b in border)
        x0, y0, x1, y1 = l["ink_box"]
        assert m - 1e-9 <= x0 and x1 <= l["width"] - m + 1e-9
        assert (pixels != l["background"]).any()


def test_resume_rewrites_only_the_missing_shard(reference, corpus, scheduler, tmp_path):
    out = tmp_path / "ds"
    shutil.copytree(reference, out)
    before = {n: os.stat(out / n).st_mtime_ns for n in os.listdir(out)}
    # An interrupted shard: its tar written, its label file (the completion mark) not, and a
    # temporary file left behind.
    os.unlink(out / "shard-00002.jsonl")
    (out / ".tmp-shard-00002.jsonl.x1y2").write_bytes(b"half a line")
    r = run_dataset(args(corpus, out, "--scheduler", scheduler))
    assert r.returncode == 0, r.stderr
    assert "resuming" in r.stderr and "3 of 4 shards already done" in r.stderr
    assert dataset_files(out) == dataset_files(reference)
    after = {n: os.stat(out / n).st_mtime_ns for n in os.listdir(out)}
    changed = sorted(n for n in after if after[n] != before.get(n))
    assert changed == ["shard-00002.jsonl", "shard-00002.tar"]


def test_rerun_of_a_finished_dataset_draws_nothing(reference, corpus, tmp_path):
    out = tmp_path / "ds"
    shutil.copytree(reference, out)
    r = run_dataset(args(corpus, out, "--workers", 1))
    assert r.returncode == 0, r.stderr
    assert "0 samples in 0 shards" in r.stderr
    assert dataset_files(out) == dataset_files(reference)


@pytest.mark.parametrize("change,key", [(["--seed", "12"], "seed"),
                                         (["--sizes", "12,21"], "sizes")])
def test_resume_with_other_arguments_is_refused(reference, corpus, tmp_path, change, key):
    out = tmp_path / "ds"
    shutil.copytree(reference, out)
    os.unlink(out / "shard-00001.jsonl")
    a = args(corpus, out, "--workers", 1)
    i = a.index(change[0])
    a[i + 1] = change[1]
    r = run_dataset(a)
    assert r.returncode == 1, r.stderr
    assert f"differing: {key})" in r.stderr and "Traceback" not in r.stderr
    assert not (out / "shard-00001.jsonl").exists()


def test_killed_worker_loses_no_shard(reference, corpus, tmp_path):
    # TEST-ONLY hook (bezel/dataset/task.py): the first attempt at shard 1 kills its worker
    # process with os._exit; the scheduler reruns the task on the restarted worker.
    marker = tmp_path / "killed"
    out = tmp_path / "ds"
    env = package_env(BEZEL_DATASET_TEST_KILL_SHARD=f"1:{marker}")
    r = run_dataset(args(corpus, out, "--workers", 2), env=env)
    assert r.returncode == 0, r.stderr
    assert marker.exists()  # the fault did happen
    assert dataset_files(out) == dataset_files(reference)


def test_undrawable_sample_stops_the_run_naming_it(corpus, scheduler, tmp_path):
    # 16384 px is a valid em size, but a line of text at it is wider than any image bezel fills.
    out = tmp_path / "ds"
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", out, "--sizes", "16384", "--count", 1,
                     "--scheduler", scheduler])
    assert r.returncode == 1, r.stderr
    assert "sample 0 (corpus line 1, font 'DejaVuSans.ttf', 16384 px)" in r.stderr
    assert "more than 16384 px" in r.stderr and "Traceback" not in r.stderr
    assert not [n for n in os.listdir(out) if n.startswith("shard")]


def test_skip_invalid_drops_bad_lines_and_says_how_many(scheduler, tmp_path):
    corpus = tmp_path / "mixed.txt"
    corpus.write_bytes(b"first line\nbad \xff byte\nthird line\n\xc0\xaf overlong\nfifth\n")
    out = tmp_path / "ds"
    r = run_dataset([corpus, "--fonts", DEJAVU, "--out", out, "--skip-invalid", "--shard-size",
                     2, "--scheduler", scheduler])
    assert r.returncode == 0, r.stderr
    assert "skipped 2 corpus lines of invalid UTF-8 (--skip-invalid)" in r.stderr
    labels = read_labels(out)
    assert [(l["line"], l["text"]) for l in labels] == [(1, "first line"), (3, "third line"),
                                                        (5, "fifth")]
