"""The native engine of ``safestate check --engine native`` (docs/checker-performance.md).

`translate.py` turns the model's Init, Next, invariants and constraints into the
program tree the C++ core (`safestate._tla_native`) evaluates; `search.py` runs it
and turns its outcome into the Python engine's `CheckResult`.
"""

from pathlib import Path

_BINDINGS = Path(__file__).resolve().parents[4] / "bindings" / "python"


def native_core_sources() -> list[Path]:
    """The core's C++ sources, where they are at hand (a source checkout; else none): part
    of the checker's "version" in cache keys (state graphs, evidence steps), so a change
    to the core alone never reuses an old result.  Every file of the core, however it is
    split (`tla_native*` files and a `tla_native/` folder)."""
    if not _BINDINGS.is_dir():
        return []
    files = [*_BINDINGS.glob("tla_native*.cpp"), *_BINDINGS.glob("tla_native*.hpp"), *_BINDINGS.glob("tla_native/**/*")]
    return sorted(f for f in files if f.is_file())
