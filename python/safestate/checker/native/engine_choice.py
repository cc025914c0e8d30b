"""``--engine python|native|auto``: which engine searches the state space.

* ``python``: the reference evaluator (`checker/explore.py`), every feature.
* ``native``: the C++ core (`search.py`); a model outside its subset is refused
  with the construct's file:line:col and "not supported by the native engine".
* ``auto`` (the default of ``safestate check``): the native core when it accepts the
  model, else Python (said in one line on stderr).

An evaluation error inside the core (e.g. ``Head(<<>>)``) is never reported by the
core itself: the model is checked again with the Python engine, which gives TLC's
exact message, counts and trace (said on stderr).
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Callable

from ..explore import CheckResult, explore_states
from ..model import Model

if TYPE_CHECKING:
    from .search import NativeRun

ENGINES = ("python", "native", "auto")


def _note(msg: str) -> None:
    """One line on stderr (a message with line breaks folded), never silence."""
    print("safestate check: " + " ".join(msg.split()), file=sys.stderr, flush=True)


def _translate(model: Model, graph: bool) -> "NativeRun | str":
    """The model translated for the core, or why the native engine cannot run this
    check; raises `UnsupportedError` (file:line:col) for a construct outside its subset."""
    if graph:
        return "--graph needs the Python engine"
    from .search import NativeRun
    return NativeRun(model)


def check(model: Model, engine: str, workers: int = 1, graph: bool = False, max_memory_mb: int | None = None,
          progress: Callable[[str], None] | None = None) -> CheckResult:
    if engine == "python":
        return explore_states(model, workers=workers, graph=graph, max_memory_mb=max_memory_mb, progress=progress)
    from ...tla.errors import UnsupportedError
    try:
        run = _translate(model, graph)
    except UnsupportedError as e:
        if engine == "native":
            raise
        run = str(e)
    if isinstance(run, str):
        why = run
        if engine == "native":
            raise UnsupportedError(f"{why}: not supported by the native engine")
        _note(f"{why}; using the Python engine")
        return explore_states(model, workers=workers, graph=graph, max_memory_mb=max_memory_mb, progress=progress)
    from .search import explore_native
    result, error = explore_native(model, max_memory_mb, progress, run, workers)
    if result is None:
        _note(f"the native engine stopped at an evaluation error ({error}); checking again with the Python "
              f"engine for TLC's report")
        return explore_states(model, workers=1, graph=graph, max_memory_mb=max_memory_mb, progress=progress)
    return result
