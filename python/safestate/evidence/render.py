"""The HTML of the evidence package: index.html (summary per system, traceability
matrix, gap list) and one page per system (diagrams, proofs, conformance, mutants).
Static, no script, no external resource: every link and image is a file of the package."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from html import escape
from typing import Any

from .matrix import Entry, Gap, Matrix, UnreachableRow, check_verdict, conform_summary, proofs_by_invariant
from .steps import SystemRuns

CSS = """
body{font-family:Helvetica,Arial,sans-serif;font-size:13px;margin:1.5em;color:#111}
h1{font-size:22px}h2{font-size:18px;margin-top:1.6em}h3{font-size:15px}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;padding:3px 6px;vertical-align:top;text-align:left}
th{background:#eee}code{font-size:12px}.gap{background:#fdd;color:#900;font-weight:bold}
.ok{color:#060}.bad{color:#b00;font-weight:bold}.muted{color:#666}
table.matrix td{font-size:12px}table.matrix td:first-child{white-space:nowrap}
ul.compact{margin:0;padding-left:1.1em}img.diagram{max-width:100%;border:1px solid #ccc;background:#fff}
nav a{margin-right:1em}
"""


@dataclass
class SystemPage:
    runs: SystemRuns
    href: str
    diagrams: list[tuple[str, str, str]] = field(default_factory=list)   # (title, svg href, note)
    mutant_html: list[str] = field(default_factory=list)
    figures: dict[str, Any] = field(default_factory=dict)
    raw: list[tuple[str, str]] = field(default_factory=list)             # (title, href)


def page(title: str, body: str) -> str:
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{escape(title)}</title>'
            f"<style>{CSS}</style></head><body>{body}</body></html>\n")


def _count(n: object) -> str:
    """A figure with thousands separators, or '?' when the step did not give it."""
    return f"{n:,}" if isinstance(n, int) else "?"


def _status(ok: bool, text: str) -> str:
    return f'<span class="{"ok" if ok else "bad"}">{escape(text)}</span>'


def summary_row(p: SystemPage, test_counts: dict[str, int]) -> str:
    r = p.runs
    check = r.check.json() if r.check else None
    chk = (f"{check.get('result')}: {check.get('distinct_states'):,} distinct, {check.get('states_generated'):,} "
           f"generated, depth {check.get('depth')}") if isinstance(check, dict) and "distinct_states" in check else \
        f"exit {r.check.returncode}"
    proofs = proofs_by_invariant(r)
    proved = sum(1 for x in proofs.values() if x.get("status") == "proved")
    prf = _status(proved == len(proofs) and bool(proofs), f"{proved}/{len(proofs)} proved") if r.prove else \
        '<span class="gap">no proof plan</span>'
    conf = conform_summary(r)
    if conf:
        cf = _status(conf.get("mismatches") == 0 and conf.get("transitions_covered") == conf.get("transitions_total"),
                     f"{conf.get('transitions_covered'):,}/{conf.get('transitions_total'):,} transitions, "
                     f"{conf.get('mismatches')} mismatches, {len(conf.get('rows_taken', []))} rows taken, "
                     f"{conf.get('hypothesis_steps'):,} Hypothesis steps")
    elif r.conform:
        cf = _status(False, f"exit {r.conform.returncode}: {r.conform.stderr.strip()[-200:]}")
    else:
        cf = '<span class="gap">no conformance (no binding/adapter)</span>'
    killed = sum(1 for m in r.mutants if m.killed)
    muts = _status(killed == len(r.mutants), f"{killed}/{len(r.mutants)} killed") if r.mutants else \
        '<span class="gap">no mutants</span>'
    tests = f"{test_counts.get('passed', 0)} passed, {test_counts.get('failed', 0)} failed" + (
        f", {test_counts['not run']} not run" if test_counts.get("not run") else "")
    return (f'<tr><td><a href="{p.href}">{escape(r.system.name)}</a></td>'
            f"<td>{p.figures.get('control_states', '?')}</td><td>{_count(p.figures.get('transitions'))}</td>"
            f"<td>{len(p.figures.get('invariants', []))}</td><td>{_status(check_verdict(r) == 'success', chk)}</td>"
            f"<td>{prf}</td><td>{cf}</td><td>{muts}</td><td>{tests}</td></tr>")


def _ul(items: list[str]) -> str:
    return '<ul class="compact">' + "".join(f"<li>{i}</li>" for i in items) + "</ul>" if items else ""


def _gapcell(text: str) -> str:
    return f'<td class="gap">{escape(text)}</td>'


def matrix_row(e: Entry, unreachable: frozenset[tuple[str, str]] = frozenset()) -> str:
    rid = e.req.id
    if e.outside:
        return (f'<tr class="req"><td id="{escape(rid)}"><b>{escape(rid)}</b><br><span class="muted">'
                f'{escape(e.req.text[:140])}</span></td><td colspan="9" class="muted">not in this package: covered by '
                f'{escape(", ".join(e.outside))} (build without --system for the whole chain)</td></tr>')
    cells = [f'<td id="{escape(rid)}"><b>{escape(rid)}</b><br><span class="muted">{escape(e.req.text[:140])}</span><br>'
             f'<code>{escape(str(e.req.loc))}</code><br>{escape(", ".join(e.systems) or "")}</td>']
    cells.append(f"<td>{_ul([f'{escape(r.id)} <code>{escape(str(r.loc))}</code>' for r in e.rows])}</td>"
                 if e.rows else _gapcell("no design row"))
    if e.cpp_rows:
        items = []
        for c in e.cpp_rows:
            taken = "" if c.taken is None else (" ✓ fired" if c.taken else ' <span class="muted">unreachable by '
                                                  'construction</span>' if (c.system, c.id) in unreachable else
                                                  ' <span class="bad">never fired</span>')
            items.append(f"{escape(c.id)} <code>{escape(', '.join(map(str, c.locs[:2])))}</code>{taken}")
        cells.append(f"<td>{_ul(items)}</td>")
    else:
        cells.append(_gapcell("no C++ row found"))
    ops = [f"<code>{escape(d.name)}</code> <code>{escape(str(d.loc))}</code>" for d in e.operators[:8]]
    if len(e.operators) > 8:
        ops.append(f"… {len(e.operators) - 8} more")
    invs = [f"<b><code>{escape(i.name)}</code></b> <code>{escape(str(i.loc))}</code>" for i in e.invariants]
    cells.append(f"<td>{_ul(invs + ops)}</td>" if invs or ops else _gapcell("no model operator or invariant"))
    checks = [_status(i.check == "success", f"{i.system}: {i.check}") for i in e.invariants]
    cells.append(f"<td>{'<br>'.join(sorted(set(checks)))}</td>" if checks else _gapcell("not model-checked"))
    proofs = []
    for i in e.invariants:
        p = i.proof
        if p is None:
            proofs.append(f'<span class="bad">{escape(i.name)}: no proof</span>')
        else:
            k = f", k={p.get('k')}" if p.get("k") is not None else ""
            proofs.append(_status(p.get("status") == "proved",
                                  f"{i.name}: {p.get('status')} ({p.get('engine')}{k}, {p.get('seconds')} s)"))
    cells.append(f"<td>{'<br>'.join(proofs)}</td>" if proofs else _gapcell("not proved"))
    confs = [_status(c.get("mismatches") == 0, f"{n}: {c.get('transitions_covered'):,}/{c.get('transitions_total'):,} "
                     f"transitions, {c.get('mismatches')} mismatches") for n, c in e.conformance.items()]
    cells.append(f"<td>{'<br>'.join(confs)}</td>" if confs else _gapcell("no conformance"))
    muts = [f"{escape(i.name)}: {escape(', '.join(i.mutants))}" if i.mutants else
            f'<span class="bad">{escape(i.name)}: no killing mutant</span>' for i in e.invariants]
    cells.append(f"<td>{'<br>'.join(muts)}</td>" if muts else _gapcell("no mutant"))
    tests = [f"{_status(o == 'passed', o)} <code>{escape(t.name)}</code> <code>{escape(str(t.loc))}</code>"
             + (' <span class="muted">(req marker)</span>' if e.req.id in t.declared else "") for t, o in e.tests[:12]]
    if len(e.tests) > 12:
        passed = sum(1 for _, o in e.tests[12:] if o == "passed")
        tests.append(f"… {len(e.tests) - 12} more ({passed} passed)")
    cells.append(f"<td>{_ul(tests)}</td>" if tests else _gapcell("no test"))
    cells.append(f"<td>{_ul([f'<span class=bad>{escape(g.kind)}</span>: {escape(g.detail)}' for g in e.gaps])}</td>"
                 if e.gaps else '<td class="ok">none</td>')
    return f'<tr class="req">{"".join(cells)}</tr>'


MATRIX_HEAD = ("<tr><th>requirement</th><th>design-page rows</th><th>C++ table rows</th><th>model invariants "
               "and operators</th><th>model check</th><th>proof (engine, k, time)</th><th>conformance</th>"
               "<th>killing mutants</th><th>tests (GoogleTest / pytest)</th><th>gaps</th></tr>")


def gap_table(gaps: list[Gap]) -> str:
    by_kind = Counter(g.kind for g in gaps)
    head = "".join(f"<li><b>{escape(k)}</b>: {n}</li>" for k, n in sorted(by_kind.items()))
    rows = "".join(f'<tr><td class="gap">{escape(g.kind)}</td><td><code>{escape(g.subject)}</code></td>'
                   f"<td>{escape(g.detail)}</td></tr>" for g in gaps)
    return (f'<p class="{"bad" if gaps else "ok"}" id="gap-count">{len(gaps)} gaps</p><ul>{head}</ul>'
            f"<table><tr><th>gap</th><th>subject</th><th>detail</th></tr>{rows}</table>")


def unreachable_table(rows: list[UnreachableRow]) -> str:
    if not rows:
        return '<p class="muted">none</p>'
    body = "".join(f'<tr id="unreachable-{escape(u.why.id)}"><td><code>{escape(u.why.page)} {escape(u.why.id)}</code>'
                   f"</td><td>{escape(u.system)}</td><td>{escape(u.why.reason)}<br><code>{escape(str(u.why.loc))}</code>"
                   f"</td><td>{escape(u.argument)}</td></tr>" for u in rows)
    return (f"<p>{len(rows)} rows are never exercised because they cannot fire: not counted as gaps; each with the "
            "design page's reason and the argument that it indeed never fires.</p><table><tr><th>row</th>"
            f"<th>system</th><th>reason (by construction)</th><th>argument</th></tr>{body}</table>")


def index_html(pages: list[SystemPage], m: Matrix, header: dict[str, Any], extras: list[tuple[str, str]],
               test_counts: dict[str, dict[str, int]]) -> str:
    tools = "".join(f"<tr><th>{escape(k)}</th><td><code>{escape(str(v))}</code></td></tr>"
                    for k, v in header["tools"].items())
    summary = "".join(summary_row(p, test_counts.get(p.runs.system.name, {})) for p in pages)
    unreachable = frozenset((u.system, u.why.id) for u in m.unreachable)
    raw = "".join(f'<li><a href="{h}">{escape(t)}</a></li>' for t, h in extras)
    body = f"""<h1>safestate evidence package</h1>
<nav><a href="#summary">summary</a><a href="#matrix">traceability matrix</a><a href="#gaps">gaps</a>
<a href="#unreachable">unreachable rows</a>
<a href="#artefacts">raw artefacts</a><a href="manifest.json">manifest.json</a></nav>
<p>Built {escape(header['date'])} on {escape(header['machine']['hostname'])} ({escape(header['machine']['system'])}).
Verify with <code>safestate evidence --verify DIR</code>: it re-hashes every input and output listed in
<a href="manifest.json">manifest.json</a> and re-runs the model check of each CI cfg.</p>
<table>{tools}</table>
<h2 id="summary">Systems</h2>
<table><tr><th>system</th><th>control states</th><th>transitions</th><th>invariants</th><th>model check</th>
<th>proofs</th><th>conformance</th><th>model mutants</th><th>unit tests (named after its requirements)</th></tr>
{summary}</table>
<h2 id="matrix">Traceability matrix ({len(m.entries)} requirements)</h2>
<p>Every requirement ID of REQUIREMENTS.md, in its order. A red cell is a gap.</p>
<table class="matrix" id="matrix-table">{MATRIX_HEAD}{''.join(matrix_row(e, unreachable) for e in m.entries)}</table>
<h2 id="gaps">Gaps</h2>{gap_table(m.gaps)}
<h2 id="unreachable">Rows unreachable by construction</h2>{unreachable_table(m.unreachable)}
<h2 id="artefacts">Raw artefacts</h2><ul>{raw}</ul>"""
    return page("safestate evidence", body)


def system_html(p: SystemPage) -> str:
    r = p.runs
    s = r.system
    diagrams = "".join(f'<h3>{escape(t)}</h3><p class="{"muted" if h else "gap"}">{escape(n)}</p>'
                       + (f'<img class="diagram" src="{h}" alt="{escape(t)}">' if h else "") for t, h, n in p.diagrams)
    proofs = "".join(f"<tr><td><code>{escape(n)}</code></td><td>{_status(x.get('status') == 'proved', str(x.get('status')))}</td>"
                     f"<td>{escape(str(x.get('engine')))}</td><td>{x.get('k')}</td><td>{x.get('seconds')}</td>"
                     f"<td>{escape(x.get('note') or '')}</td></tr>" for n, x in proofs_by_invariant(r).items())
    raw = "".join(f'<li><a href="{h}">{escape(t)}</a></li>' for t, h in p.raw)
    conf = conform_summary(r)
    conf_html = "<pre>" + escape("\n".join(f"{k}: {v}" for k, v in conf.items() if k not in ("reproducers",))) + \
        "</pre>" if conf else '<p class="gap">no conformance run</p>'
    body = f"""<p><a href="../index.html">← summary</a></p><h1>{escape(s.name)}</h1><p>{escape(s.summary)}</p>
<p>model <code>{escape(str(s.model.relative_to(s.root)))}</code>, CI cfg <code>{escape(str(s.ci_config.relative_to(s.root)))}</code>,
design page <code>{escape(str(s.design.relative_to(s.root)))}</code></p>
<h2>Diagrams</h2>{diagrams}
<h2>Proofs</h2><table><tr><th>invariant</th><th>status</th><th>engine</th><th>k</th><th>seconds</th><th>note</th></tr>{proofs}</table>
<h2>Conformance</h2>{conf_html}
<h2>Model mutants and their counterexamples</h2>{''.join(p.mutant_html) or '<p class="gap">no model mutants</p>'}
<h2>Raw artefacts</h2><ul>{raw}</ul>"""
    return page(f"{s.name} — safestate evidence", body)
