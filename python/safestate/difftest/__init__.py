"""Differential testing of `safestate check` against TLC.

`python -m safestate.difftest` generates small random specs (`generator.py`),
checks each with TLC (`tlc_batch.py`, many specs per JVM) and with our checker
(`ours.py`), compares verdict, violated invariant, counts, depth and exit code
(`compare.py`) and shrinks every disagreement to a small repro (`minimise.py`).
"""
