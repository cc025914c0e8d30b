"""The breadth-first search sharded over Ray actors (`safestate check --ray ADDRESS`).

The same level-synchronous search as `checker/parallel.py` (its workers are
`checker/shard_worker.py`), with the workers as Ray actors that each load the model
from its text, and the batches and key arrays carried by Ray's object store
(`ray_link.py`); the coordinator is this process (`ray_search.py`), which reaches or
starts the cluster (`cluster.py`).  Results are one worker's, by the same construction.
"""
