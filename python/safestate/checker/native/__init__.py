"""The native engine of ``safestate check --engine native`` (docs/checker-performance.md).

`translate.py` turns the model's Init, Next, invariants and constraints into the
program tree the C++ core (`safestate._tla_native`) evaluates; `search.py` runs it
and turns its outcome into the Python engine's `CheckResult`.
"""
