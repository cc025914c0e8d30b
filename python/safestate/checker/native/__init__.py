"""The native engine of ``safestate check --engine native`` (docs/checker-performance.md).

`translate.py` turns the model's Init, Next, invariants and constraints into the
program tree the C++ core (`safestate._tla_native`) evaluates; `search.py` runs it
and turns its outcome into the Python engine's `CheckResult`.
"""

from pathlib import Path

# The core's C++ source, where the sources are at hand (a source checkout): part of the
# checker's "version" in cache keys (state graphs, evidence steps), so a change to the
# core alone never reuses an old result.
NATIVE_CORE_SOURCE = Path(__file__).resolve().parents[4] / "bindings" / "python" / "tla_native_module.cpp"
