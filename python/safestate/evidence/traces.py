"""A counterexample (ITF trace) rendered for a reader: a step table (the variables each
step changed) and a sequence diagram (SVG, drawn here: the environment sends each
step's action to the model, which notes what changed; the last step in red)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from html import escape
from typing import Any


@dataclass
class Step:
    index: int
    action: str
    changes: dict[str, str]      # variable -> new value (compact text); every variable at step 0


def compact(v: Any) -> str:
    if isinstance(v, dict):
        if "#bigint" in v:
            return str(v["#bigint"])
        if "#set" in v:
            return "{" + ", ".join(compact(x) for x in v["#set"]) + "}"
        if "#tup" in v:
            return "<<" + ", ".join(compact(x) for x in v["#tup"]) + ">>"
        if "#map" in v:
            return "(" + ", ".join(f"{compact(k)} :> {compact(x)}" for k, x in v["#map"]) + ")"
        if "#unserializable" in v:
            return str(v["#unserializable"])
        return "[" + ", ".join(f"{k} |-> {compact(x)}" for k, x in v.items()) + "]"
    if isinstance(v, list):
        return "<<" + ", ".join(compact(x) for x in v) + ">>"
    if isinstance(v, bool):
        return "TRUE" if v else "FALSE"
    return json.dumps(v) if isinstance(v, str) else str(v)


def steps(itf: dict[str, Any]) -> list[Step]:
    out: list[Step] = []
    prev: dict[str, str] = {}
    for i, st in enumerate(itf.get("states", [])):
        meta = st.get("#meta", {}) or {}
        params = meta.get("params") or {}
        action = str(meta.get("action") or ("Init" if i == 0 else "?"))
        if params:
            action += "(" + ", ".join(f"{k} = {compact(v)}" for k, v in params.items()) + ")"
        cur = {k: compact(v) for k, v in st.items() if k != "#meta"}
        out.append(Step(i, action, {k: v for k, v in cur.items() if prev.get(k) != v}))
        prev = cur
    return out


def step_table_html(ss: list[Step], control: str | None) -> str:
    rows = []
    for s in ss:
        ctl = s.changes.get(control, "") if control else ""
        changes = "<br>".join(f"<code>{escape(k)} = {escape(_clip(v, 160))}</code>" for k, v in s.changes.items()
                              if k != control)
        rows.append(f"<tr><td>{s.index}</td><td><code>{escape(_clip(s.action, 200))}</code></td>"
                    f"<td><b>{escape(ctl)}</b></td><td>{changes}</td></tr>")
    head = f"<tr><th>step</th><th>action</th><th>{escape(control or '')}</th><th>variables changed</th></tr>"
    return f'<table class="steps">{head}{"".join(rows)}</table>'


def _clip(s: str, n: int) -> str:
    return s if len(s) <= n else s[: n - 1] + "…"


def sequence_svg(ss: list[Step], system: str, control: str | None, verdict: str) -> str:
    """Two lifelines (environment, model); one arrow per step with its action, a note
    with the control state (and how many other variables changed)."""
    w, top, dy = 900, 60, 46
    xe, xm = 140, 520
    h = top + dy * (len(ss) + 1) + 30
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" '
           f'font-family="Helvetica, Arial, sans-serif" font-size="12">',
           '<defs><marker id="arrow" markerWidth="10" markerHeight="7" refX="10" refY="3.5" orient="auto">'
           '<polygon points="0 0, 10 3.5, 0 7"/></marker></defs>']
    for x, name in ((xe, "environment / inputs"), (xm, f"{system} model")):
        out.append(f'<rect x="{x - 90}" y="10" width="180" height="28" rx="4" fill="#eef" stroke="#447"/>')
        out.append(f'<text x="{x}" y="29" text-anchor="middle">{escape(name)}</text>')
        out.append(f'<line x1="{x}" y1="38" x2="{x}" y2="{h - 10}" stroke="#888" stroke-dasharray="4 3"/>')
    for i, s in enumerate(ss):
        y = top + dy * i
        last = i == len(ss) - 1
        color = "#c00" if last else "#000"
        out.append(f'<line x1="{xe}" y1="{y}" x2="{xm}" y2="{y}" stroke="{color}" marker-end="url(#arrow)"/>')
        out.append(f'<text x="{(xe + xm) // 2}" y="{y - 5}" text-anchor="middle" fill="{color}">'
                   f'{i}: {escape(_clip(s.action, 60))}</text>')
        ctl = s.changes.get(control, "") if control else ""
        others = len([k for k in s.changes if k != control])
        note = (f"{control} = {ctl}; " if ctl else "") + f"{others} other variable(s) changed"
        out.append(f'<rect x="{xm + 10}" y="{y - 14}" width="{w - xm - 20}" height="22" fill="{"#fdd" if last else "#ffe"}" '
                   f'stroke="{color}"/>')
        out.append(f'<text x="{xm + 16}" y="{y + 1}" fill="{color}">{escape(_clip(note, 62))}</text>')
    if ss:
        y = top + dy * (len(ss) - 1) + 28
        out.append(f'<text x="{xm + 16}" y="{y}" fill="#c00" font-weight="bold">{escape(_clip(verdict, 62))}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
