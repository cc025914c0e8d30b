"""The operator panel's state diagram: a hierarchical Graphviz layout of the C++ table.

The table comes from the binding's JSON export (the rows the control cycle runs). The
layout is made to be read at the panel's normal size, not zoomed:

* states grouped in clusters by mode (start-up, automatic, manual), then the states that
  stops lead into, top to bottom by how hard the stop is (Cat 1 / Cat 2, then Cat 0);
* one edge per (source, target) pair, labelled with its row ids only (at most three, then
  "+n"); the full rows (event, guard, stop category) are in the edge's tooltip;
* a row from more than three states (most stops) is drawn once, from a small
  "any of n states" node whose tooltip names them;
* self-loops (rows that keep the state) and rejected commands are left out: they never
  move the highlighted state.

Each edge's SVG id is "rows:" + its row ids joined by "," so the panel can highlight the
edge of the row that fired (www/panel.js).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any

# Clusters, top to bottom: the modes, then the states ever harder stops lead into.
CLUSTERS: tuple[tuple[str, str, tuple[str, ...]], ...] = (
    ("start", "start-up", ("BOOT", "IDLE", "ARMING")),
    ("auto", "automatic", ("AUTO_IDLE", "AUTO_RUNNING")),
    ("manual", "manual (T1 / T2)", ("MANUAL_IDLE", "MANUAL_JOGGING")),
    ("stop", "Cat 1 / Cat 2 stop", ("STOPPING", "HOLD")),
    ("safe", "Cat 0: power off", ("ESTOP_ACTIVE", "ESTOP_RESET_NEEDED", "ERROR_LOCKOUT")),
)
STOP_COLOURS = {"CAT0": "#c62828", "CAT1": "#ef6c00", "CAT2": "#f9a825"}
MAX_LABEL_ROWS = 3
FAN_IN = 3  # a row from more states than this is drawn from one "any of" node


@dataclass
class Edge:
    tail: str
    head: str
    rows: list[dict[str, Any]] = field(default_factory=list)

    @property
    def row_ids(self) -> list[str]:
        return [r["id"] for r in self.rows]


def _row_text(row: dict[str, Any]) -> str:
    guard = "" if row["guard"] == "always" else f" [{row['guard']}]"
    stop = "" if row["stop_category"] in ("KEEP", "NONE") else f" / {row['stop_category']}"
    return f"{row['id']} {row['event']}{guard}{stop}"


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _edges(rows: list[dict[str, Any]]) -> tuple[list[Edge], dict[tuple[str, ...], str]]:
    """The merged edges, and the "any of" node of each wide source set."""
    edges: dict[tuple[str, str], Edge] = {}
    any_nodes: dict[tuple[str, ...], str] = {}
    for row in rows:
        if row["kind"] != "ENTER":
            continue
        sources = tuple(row["effective_source"])
        for target in row["targets"]:
            if len(sources) > FAN_IN:
                tails = [any_nodes.setdefault(sources, f"ANY_{len(any_nodes) + 1}")]
            else:
                tails = [s for s in sources if s != target]
            for tail in tails:
                edges.setdefault((tail, target), Edge(tail, target)).rows.append(row)
    return list(edges.values()), any_nodes


def _edge_line(edge: Edge) -> str:
    ids = edge.row_ids
    label = " ".join(ids[:MAX_LABEL_ROWS]) + (f" +{len(ids) - MAX_LABEL_ROWS}" if len(ids) > MAX_LABEL_ROWS else "")
    stops = sorted(r["stop_category"] for r in edge.rows if r["stop_category"] in STOP_COLOURS)
    colour = STOP_COLOURS[stops[0]] if stops else "#424242"  # the hardest stop (CAT0 sorts first)
    attrs = [f"id={_quote('rows:' + ','.join(ids))}", f"label={_quote(label)}",
             f"tooltip={_quote(chr(10).join(_row_text(r) for r in edge.rows))}",
             f"color={_quote(colour)}", f"fontcolor={_quote(colour)}"]
    return f"  {edge.tail} -> {edge.head} [{', '.join(attrs)}];"


def panel_dot(table_json: str) -> str:
    """The DOT text of the panel's diagram for the binding's transition_table_json()."""
    rows: list[dict[str, Any]] = json.loads(table_json)["rows"]
    out = [
        "digraph SystemStateManager {",
        '  rankdir=TB; newrank=true; nodesep=0.3; ranksep=0.4; fontname="Helvetica";',
        '  node [shape=box, style="rounded,filled", fillcolor="#ffffff", fontname="Helvetica", fontsize=14];',
        '  edge [fontname="Helvetica", fontsize=12, arrowsize=0.7];',
    ]
    for name, label, states in CLUSTERS:
        out.append(f"  subgraph cluster_{name} {{")
        out.append(f'    label={_quote(label)}; style="rounded,dashed"; color="#9e9e9e"; fontsize=12;')
        out.extend(f"    {s};" for s in states)
        out.append("  }")
    edges, any_nodes = _edges(rows)
    for sources, node in any_nodes.items():
        out.append(f'  {node} [shape=plaintext, style="", fontsize=12, label={_quote(f"any of {len(sources)}")}, '
                   f"tooltip={_quote(', '.join(sources))}];")
    out.extend(_edge_line(e) for e in edges)
    out.append("}")
    return "\n".join(out) + "\n"
