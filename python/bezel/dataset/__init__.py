"""bezel.dataset: render a text corpus into a sharded, labelled image dataset, in parallel on Dask.

Run it as `python3 -m bezel.dataset CORPUS --fonts F --out DIR` (docs/dataset.md). The modules:
corpus (reading and checking the text), fonts (finding font files), params (the run's settings
and each sample's seeded parameters), render (drawing one sample), shards (atomic shard files),
manifest (the run's parameters, for resume), task (one shard, in a worker), driver (Dask),
progress (the stderr report), cli (arguments and exit codes).
"""
