"""The progress report on stderr: shards done, samples done and samples per second.

On a terminal, one line redrawn in place (at most every REDRAW_S seconds); otherwise (a log
file, CI) a plain line every PLAIN_EVERY_S seconds and one at the end, so logs stay short.
"""
from __future__ import annotations

import sys
import time

REDRAW_S = 0.1
PLAIN_EVERY_S = 5.0
BAR_WIDTH = 24


class Progress:
    def __init__(self, shards_total: int, shards_done: int, samples_total: int,
                 samples_done: int, stream=None, enabled: bool = True):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled
        self.tty = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.shards_total, self.shards_done = shards_total, shards_done
        self.samples_total, self.samples_done = samples_total, samples_done
        self.new_samples = 0
        self.start = time.monotonic()
        self.last = float("-inf")

    def rate(self) -> float:
        elapsed = time.monotonic() - self.start
        return self.new_samples / elapsed if elapsed > 0 else 0.0

    def line(self) -> str:
        frac = self.shards_done / self.shards_total if self.shards_total else 1.0
        filled = int(frac * BAR_WIDTH)
        bar = "#" * filled + "." * (BAR_WIDTH - filled)
        return (f"[{bar}] {self.shards_done}/{self.shards_total} shards, "
                f"{self.samples_done}/{self.samples_total} samples, {self.rate():.1f} samples/s")

    def advance(self, samples: int) -> None:
        self.shards_done += 1
        self.samples_done += samples
        self.new_samples += samples
        self.show()

    def show(self, final: bool = False) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if self.tty:
            if final or now - self.last >= REDRAW_S:
                # \x1b[K clears what a longer previous line left to the right.
                self.stream.write("\r" + self.line() + "\x1b[K" + ("\n" if final else ""))
                self.stream.flush()
                self.last = now
        elif final or now - self.last >= PLAIN_EVERY_S:
            self.stream.write("bezel.dataset: " + self.line() + "\n")
            self.stream.flush()
            self.last = now
