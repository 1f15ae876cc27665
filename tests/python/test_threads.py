"""The GIL is released while bezel works, and one Font serves many threads at once."""

import threading
import time

import numpy as np

import bezel
from conftest import DEJAVU


def long_render_text(font):
    """Text whose render takes at least 0.2 s here (doubled until it does)."""
    text = "The quick brown fox jumps over the lazy dog. " * 50
    while True:
        start = time.perf_counter()
        font.render(text, width=800)
        if time.perf_counter() - start >= 0.2 or len(text) > 1_000_000:
            return text
        text += text


def python_progress_during(call):
    """Runs `call` on a thread while this thread counts in pure Python (which runs only while it
    holds the GIL). Returns (the call's duration, the longest stretch this thread was stopped
    during it, how many times it counted meanwhile)."""
    span = {}

    def work():
        span["start"] = time.perf_counter()
        call()
        span["end"] = time.perf_counter()

    thread = threading.Thread(target=work)
    ticks = []
    thread.start()
    while thread.is_alive():
        ticks.append(time.perf_counter())
    thread.join()
    during = [t for t in ticks if span["start"] <= t <= span["end"]]
    gaps = np.diff([span["start"], *during, span["end"]])
    return span["end"] - span["start"], gaps.max(), len(during)


def assert_gil_released(call):
    duration, longest_stop, count = python_progress_during(call)
    # Held for the whole call, the GIL would stop the counting thread for `duration`; released,
    # it keeps counting (stopped only for the interpreter's switch interval and the machine's
    # load).
    assert count > 100 and longest_stop < duration / 2, (duration, longest_stop, count)


def test_render_releases_the_gil():
    font = bezel.Font(DEJAVU, size=14)
    text = long_render_text(font)
    assert_gil_released(lambda: font.render(text, width=800))
    assert_gil_released(lambda: font.text_path(text, width=800))


def test_fill_and_encode_release_the_gil():
    # A long zigzag: many edges crossing a large mask.
    d = "M0 0" + "".join(f"L{(k * 37) % 1500} {(k * 91) % 1500}" for k in range(40000)) + "Z"
    path = bezel.Path(d)
    mask = bezel.fill(path, 1500, 1500)
    assert_gil_released(lambda: bezel.fill(path, 1500, 1500))
    noise = np.random.default_rng(1).integers(0, 256, size=(1500, 1500), dtype=np.uint8)
    assert_gil_released(lambda: bezel.encode_png(noise, compression="small"))
    assert mask.any()


def test_one_font_on_many_threads_renders_as_on_one():
    font = bezel.Font(DEJAVU, size=18)
    texts = [f"Thread {k}: Wafer office {k * 7}" for k in range(8)]
    expected = [font.render(t) for t in texts]
    results = [None] * len(texts)
    errors = []

    def work(k):
        try:
            for _ in range(5):
                page = font.render(texts[k])
                glyph = font.glyph("g")
                assert glyph.image.size > 0
            results[k] = page
        except Exception as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(texts))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for got, want in zip(results, expected):
        assert np.array_equal(got, want)
