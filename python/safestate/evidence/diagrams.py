"""Graphviz diagrams of the evidence package: each C++ transition table and each model's
control states, with row IDs on the edges."""

from __future__ import annotations

import importlib
import re
import subprocess
from collections import defaultdict
from collections.abc import Iterable

from ..systems.registry import System
from .sources import DesignRow


class DiagramError(Exception):
    pass


def svg(dot: str) -> str:
    """The SVG Graphviz draws for `dot` (without the XML prologue: inlinable)."""
    try:
        p = subprocess.run(["dot", "-Tsvg"], input=dot, capture_output=True, text=True, timeout=300)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise DiagramError(f"graphviz dot failed: {e}") from e
    if p.returncode != 0:
        raise DiagramError(f"graphviz dot failed: {p.stderr.strip()[:300]}")
    return p.stdout[p.stdout.find("<svg"):]


def _q(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def digraph(name: str, edges: dict[tuple[str, str], set[str]], nodes: Iterable[str] = ()) -> str:
    """`edges`: (from, to) -> labels (row IDs or actions), merged into one edge each."""
    lines = [f"digraph {_q(name)} {{", '  rankdir=LR; node [shape=box, style=rounded, fontname="Helvetica", '
             'fontsize=10]; edge [fontname="Helvetica", fontsize=8];']
    for n in sorted(set(nodes) | {a for a, _ in edges} | {b for _, b in edges}):
        lines.append(f"  {_q(n)};")
    for (a, b), labels in sorted(edges.items()):
        lab = _wrap(sorted(labels))
        lines.append(f"  {_q(a)} -> {_q(b)} [label={_q(lab)}];")
    lines.append("}")
    return "\n".join(lines) + "\n"


def _wrap(labels: list[str], per_line: int = 4, most: int = 12) -> str:
    shown = labels[:most] + ([f"+{len(labels) - most} more"] if len(labels) > most else [])
    return "\n".join(" ".join(shown[i:i + per_line]) for i in range(0, len(shown), per_line))


def cpp_table_dot(system: System) -> tuple[str, str] | None:
    """(dot, source) of the system's C++ table from its binding's own DOT export (the
    flagship's); None when the binding has none (the caller draws the design-page rows)."""
    if system.conformance is None:
        return None
    try:
        core = importlib.import_module(system.conformance.binding)
    except ImportError as e:
        raise DiagramError(f"{system.name}: cannot import {system.conformance.binding}: {e}") from e
    if hasattr(core, "transition_table_dot"):
        return core.transition_table_dot(), f"{system.conformance.binding}.transition_table_dot()"
    return None


def design_rows_dot(name: str, rows: list[DesignRow]) -> str:
    """A DOT from design-page rows `| ID | from | guard | to | ...`: sources split on
    commas; `stay`, or a fourth column that is not a state name, a self-loop."""
    edges: dict[tuple[str, str], set[str]] = defaultdict(set)
    for r in rows:
        cells = [c.strip() for c in r.text.strip("|").split("|")]
        if len(cells) < 4:
            continue
        froms = [f.strip() for f in re.split(r",|\bor\b", cells[1]) if f.strip()]
        to = re.sub(r"[`(].*", "", cells[3]).strip().rstrip(",") or "stay"
        # A target that is not a state name (an action column: "send Request Control") stays.
        stays = to == "stay" or not re.fullmatch(r"[A-Z][A-Z0-9_]*", to)
        for f in froms:
            edges[(f, f if stays else to)].add(r.id)
    return digraph(name, edges)


def model_states_dot(system: System, control: str, rows_per_edge: int = 40) -> tuple[str, dict[str, int]]:
    """The model's reachable control states (the value of `control`) and the actions
    between them, from the explored state graph of the CI cfg (the on-disk graph cache);
    with conformance, each edge also carries the rows the model fires (`RowsFiredBy`)
    on up to `rows_per_edge` of its transitions.  Returns (dot, figures)."""
    from ..checker.model import load_model
    from ..conform import graph as graph_mod

    model = load_model(str(system.model), str(system.ci_config))
    if control not in model.variables:
        raise DiagramError(f"{system.manifest}: control_state {control!r} is not a variable of {system.model.name}")
    g = graph_mod.cached_explore(model)
    k = list(model.variables).index(control)
    adapter = _adapter(system, model)
    edges: dict[tuple[str, str], set[str]] = defaultdict(set)
    sampled: dict[tuple[str, str], int] = defaultdict(int)
    for s, d, ev in zip(g.src, g.dst, g.events):
        a, b = _label(g.states[s][k]), _label(g.states[d][k])
        edges[(a, b)].add(_event_label(ev))
        if adapter is not None and sampled[(a, b)] < rows_per_edge:
            sampled[(a, b)] += 1
            try:
                rows = adapter.model_rows(g.states[s], ev)
            except (ValueError, TypeError, KeyError):
                rows = None   # an event without a row operator application (e.g. a command submission)
            edges[(a, b)].update(rows or ())
    figures = {"states": len(g.states), "transitions": len(g.src), "control_states": len({x for e in edges for x in e})}
    return digraph(f"{system.name} model", edges), figures


def _event_label(ev: object) -> str:
    """The action, with its short string parameters (Step(StandStill)); a record
    parameter (a whole input vector) is left out."""
    params = [v for _, v in getattr(ev, "params", ()) if isinstance(v, str | bool) and len(str(v)) <= 20]
    name = str(getattr(ev, "action", ev))
    return f"{name}({', '.join(map(str, params))})" if params else name


def _label(v: object) -> str:
    return v if isinstance(v, str) else str(v)


def _adapter(system: System, model: object):  # type: ignore[no-untyped-def]
    if system.conformance is None:
        return None
    try:
        from ..conform.cli import make_harness
        return make_harness(system, model).adapter  # type: ignore[arg-type]
    except Exception:  # noqa: BLE001 - without the binding the diagram still has the actions
        return None
