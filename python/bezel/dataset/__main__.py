"""python3 -m bezel.dataset: see cli.py and docs/dataset.md."""
import sys

from .cli import main

# Guarded: Dask's worker processes may import the main module of the program that started them.
if __name__ == "__main__":
    sys.exit(main())
