"""The model mutation score of each system in the evidence package (issue 28).

One page per system, `mutation/model/SYSTEM.html`, from the system's last
`safestate mutate` result (`mutate/results.py`: build/mutate/SYSTEM.json): the score,
when and on what sample it was measured, every survivor with its operator, location,
diff and difference trace -- or, where the design page justifies it (a
`[[mutate.justified]]` entry of the manifest), the justification, and then it is not a
gap -- the equivalent mutants, the timeouts and errors with their reasons, and the
killed ones with the property that killed them.  A system not measured yet says so.
"""

from __future__ import annotations

import io
import json
from html import escape
from pathlib import Path
from typing import Any

from ..mutate import results
from ..mutate.classify import Outcome
from ..mutate.report import write_trace
from . import render

PAGE_DIR = Path("mutation") / "model"


def section(system: Any) -> tuple[dict[str, Any] | None, str]:
    """(the system's last result with its justifications applied, or None; the page's HTML body)."""
    d = results.read(system)
    if d is None:
        return None, (f'<p class="gap">not measured yet: run <code>safestate mutate {escape(system.name)}</code> '
                      f"(the main job does)</p>")
    try:
        justs = results.justifications(system)
    except results.JustificationError as e:
        return d, f'<p class="bad">{escape(str(e))}</p>'
    results.justify(d, justs)
    return d, _body(d)


def _body(d: dict[str, Any]) -> str:
    c = d.get("counts", {})
    sc = d.get("score")
    what = (f"a stratified sample of {d.get('classified')} (seed {d.get('seed')})" if d.get("sampled")
            else f"all {d.get('classified')}")
    head = (f"<p><b>mutation score {'n/a' if sc is None else f'{100 * sc:.1f}%'}</b> = killed {c.get('killed', 0)} / "
            f"(killed {c.get('killed', 0)} + survived {c.get('survived', 0)}); {what} of {d.get('generated')} "
            f"generated mutants ({d.get('duplicates', 0)} duplicates left out); {c.get('equivalent', 0)} equivalent, "
            f"{c.get('timeout', 0)} timeout, {c.get('error', 0)} error (not counted); measured {escape(str(d.get('when')))}"
            f" in {d.get('seconds')} s with <code>{escape(str(d.get('cfg')))}</code>.</p>"
            f"<p>{d.get('gaps', c.get('survived', 0))} survivor(s) are gaps (a behaviour no property pins down), "
            f"{d.get('justified', 0)} justified by the design page.</p>")
    muts = d.get("mutants", [])
    parts = [head]
    survivors = [m for m in muts if m.get("status") == "survived"]
    parts.append(f"<h2>Survivors ({len(survivors)})</h2>")
    for m in survivors:
        j = m.get("justified")
        tag = (f'<span class="ok">justified</span> — <code>{escape(j["design"])}</code>: {escape(j["why"])}' if j
               else '<span class="bad">gap</span>')
        out = io.StringIO()
        write_trace(out, Outcome.from_json(m))
        parts.append(f"<h3>{escape(_where(m))} [{escape(m['operator'])}] {escape(m['definition'])}</h3>"
                     f"<p>{escape(m.get('what', ''))} · {tag}</p>"
                     f"<pre>- {escape(m.get('original', ''))}\n+ {escape(m.get('replacement', ''))}</pre>"
                     f"<p>difference trace ({escape(m.get('reason', ''))}):</p><pre>{escape(out.getvalue())}</pre>")
    for status, title in (("equivalent", "Equivalent (no observable difference; not counted)"),
                          ("timeout", "Timeout (not counted)"), ("error", "Error (not counted)"),
                          ("killed", "Killed")):
        group = [m for m in muts if m.get("status") == status]
        if not group:
            continue
        rows = "".join(f"<tr><td><code>{escape(_where(m))}</code></td><td>{escape(m['operator'])}</td>"
                       f"<td>{escape(m['definition'])}</td><td>{escape(m.get('what', ''))}</td>"
                       f"<td>{escape(_detail(m))}</td></tr>" for m in group)
        parts.append(f"<h2>{escape(title)}: {len(group)}</h2><table><tr><th>where</th><th>operator</th>"
                     f"<th>definition</th><th>change</th><th>{'killed by' if status == 'killed' else 'reason'}</th>"
                     f"</tr>{rows}</table>")
    return "".join(parts)


def _where(m: dict[str, Any]) -> str:
    return f"{m.get('file')}:{m.get('line')}:{m.get('column')}"


def _detail(m: dict[str, Any]) -> str:
    if m.get("status") == "killed" and m.get("by") == "witness":
        return f"witness {', '.join(m.get('witnesses') or [])} no longer reached"
    if m.get("status") == "killed":
        return f"{m.get('violated')} (trace {m.get('trace_length')})"
    return str(m.get("reason") or f"{m.get('pairs')} pairs")


def write(out: Path, systems: list[Any], pages: list[Any], extras: list[tuple[str, str]]) -> dict[str, int]:
    """Writes each system's page and its last result (raw JSON), links them from the
    system page and the summary; returns {system: its gaps (unjustified survivors)}."""
    (out / PAGE_DIR).mkdir(parents=True, exist_ok=True)
    gaps: dict[str, int] = {}
    by_name = {p.runs.system.name: p for p in pages}
    for s in systems:
        d, body = section(s)
        rel = PAGE_DIR / f"{s.name}.html"
        (out / rel).write_text(render.page(f"{s.name} — model mutation score",
                                           f'<p><a href="../../index.html">← summary</a></p>'
                                           f"<h1>{escape(s.name)}: model mutation score</h1>{body}"), encoding="utf-8")
        line = f"{s.name} model mutation score: {results.one_line(d)}"
        if d is not None:
            (out / PAGE_DIR / f"{s.name}.json").write_text(json.dumps(d) + "\n", encoding="utf-8")
            gaps[s.name] = int(d.get("gaps", 0))
        extras.append((line, str(rel)))
        if s.name in by_name:
            by_name[s.name].raw.append((line, "../" + str(rel)))
    return gaps
