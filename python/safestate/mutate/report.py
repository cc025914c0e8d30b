"""The mutation report: score, counts per status and operator, every survivor with its
difference trace (a table; ITF in --json and --itf-dir), the equivalents, timeouts and
errors with their reasons, the killed ones by property and by witness."""

from __future__ import annotations

from collections import Counter
from typing import Any, TextIO

from .classify import STATUSES, Outcome
from .generate import Mutant


def score(outcomes: list[Outcome]) -> float | None:
    """killed / (killed + survived); None when neither occurs.  Killed by a property or
    by a witness alike."""
    c = Counter(o.status for o in outcomes)
    n = c["killed"] + c["survived"]
    return None if n == 0 else c["killed"] / n


def summary(system: str, generated: int, mutants: list[Mutant], outcomes: list[Outcome], seconds: float,
            dropped: tuple[str, ...], sampled: bool, duplicates: int = 0) -> dict[str, Any]:
    by_id = {m.id: m for m in mutants}
    c = Counter(o.status for o in outcomes)
    per_op: dict[str, dict[str, int]] = {}
    for o in outcomes:
        k = per_op.setdefault(by_id[o.mutant].operator, dict({s: 0 for s in STATUSES}, killed_by_witness=0))
        k[o.status] += 1
        k["killed_by_witness"] += _by_witness(o)
    s = score(outcomes)
    return {
        "system": system, "generated": generated, "duplicates": duplicates, "classified": len(outcomes),
        "sampled": sampled,
        "counts": dict({k: c[k] for k in STATUSES}, killed_by_witness=sum(map(_by_witness, outcomes))),
        "score": None if s is None else round(s, 4),
        "seconds": round(seconds, 1), "cached": sum(1 for o in outcomes if o.cached),
        "not_used_invariants": list(dropped), "operators": per_op,
        "mutants": [dict(_mutant_json(by_id[o.mutant]), **o.to_json()) for o in outcomes],
    }


def _by_witness(o: Outcome) -> int:
    return int(o.status == "killed" and o.by == "witness")


def _mutant_json(m: Mutant) -> dict[str, Any]:
    return {"operator": m.operator, "definition": m.definition, "file": m.file, "line": m.line,
            "column": m.column, "what": m.what, "original": m.original, "replacement": m.patched}


def write_text(out: TextIO, s: dict[str, Any], mutants: list[Mutant], outcomes: list[Outcome]) -> None:
    by_id = {m.id: m for m in mutants}
    why = {d["mutant"]: d["justified"] for d in s.get("mutants", []) if d.get("justified")}
    c = s["counts"]
    sc = "n/a (nothing killed or survived)" if s["score"] is None else f"{100 * s['score']:.1f}%"
    sampled = " (a sample)" if s["sampled"] else ""
    by_w = c.get("killed_by_witness", 0)
    of_which = f" ({by_w} of them by a witness)" if by_w else ""
    out.write(f"{s['system']}: mutation score {sc} = killed {c['killed']} / (killed {c['killed']} + survived "
              f"{c['survived']}){of_which}; {s['classified']} of {s['generated']} mutants classified{sampled}{_dups(s)}, "
              f"{c['equivalent']} equivalent, {c['timeout']} timeout, {c['error']} error, {s['seconds']} s"
              f" ({s['cached']} from the cache)\n")
    if s.get("justified"):
        out.write(f"  {s['justified']} survivor(s) justified by the design page (not gaps), {s.get('gaps')} gap(s)\n")
    if s["not_used_invariants"]:
        out.write(f"  the original violates {', '.join(s['not_used_invariants'])}: left out of the mutants' cfg\n")
    if s.get("witnesses_not_reached"):
        out.write(f"  witnesses the original does not reach (not used): {', '.join(s['witnesses_not_reached'])}\n")
    out.write(f"  {len(s.get('witnesses', []))} reachability witness(es) of the model used\n")
    out.write("\n  operator             killed (by witness) survived equivalent timeout error\n")
    for op, k in sorted(s["operators"].items()):
        out.write(f"  {op:<20} {k['killed']:>6} {k.get('killed_by_witness', 0):>12} {k['survived']:>8} "
                  f"{k['equivalent']:>10} {k['timeout']:>7} {k['error']:>5}\n")
    for status, title in (("survived", "SURVIVED (a behaviour no property pins down)"),
                          ("equivalent", "EQUIVALENT (no observable difference; not counted)"),
                          ("timeout", "TIMEOUT (not counted)"), ("error", "ERROR (not counted)"),
                          ("witness", "KILLED BY A WITNESS (every property holds; a witness situation is no "
                                      "longer reached)"),
                          ("killed", "KILLED BY A PROPERTY")):
        group = [o for o in outcomes if (_by_witness(o) if status == "witness"
                                         else o.status == status and not _by_witness(o))]
        if not group:
            continue
        out.write(f"\n{title}: {len(group)}\n")
        for o in group:
            m = by_id[o.mutant]
            extra = ""
            if status == "killed":
                extra = f" -> {o.violated} (trace {o.trace_length})"
            elif status == "witness":
                extra = f" -> {', '.join(o.witnesses)} no longer reached"
            elif status in ("timeout", "error", "equivalent"):
                extra = f" -- {o.reason}" if o.reason else f" -- {o.pairs} pairs"
            out.write(f"  {m.file}:{m.line}:{m.column} [{m.operator}] {m.definition}: {m.what}{extra}\n")
            if status == "survived":
                out.write(f"    - {_one_line(m.original)}\n    + {_one_line(m.patched)}\n")
                if o.mutant in why:
                    out.write(f"    justified ({why[o.mutant]['design']}): {why[o.mutant]['why']}\n")
                write_trace(out, o, indent="    ")


def _dups(s: dict[str, Any]) -> str:
    n = s.get("duplicates", 0)
    return f" ({n} duplicate{'' if n == 1 else 's'} of another's text left out)" if n else ""


def _one_line(s: str, width: int = 150) -> str:
    s = " ".join(s.split())
    return s if len(s) <= width else s[:width - 3] + "..."


def write_trace(out: TextIO, o: Outcome, indent: str = "") -> None:
    """The difference trace as a table: per step the inputs, then each observable that
    differs anywhere in the trace, original | mutant, and whether each side can take the
    step at all (`no`: that input is not offered to it there)."""
    rows = o.table
    if not rows:
        return
    differing: list[str] = []
    for r in rows:
        if r["original"] is None or r["mutant"] is None:
            continue  # shown in the `takes the step` column
        a, b = r["original"], r["mutant"]
        for k in a:
            if a[k] != b[k] and k not in differing:
                differing.append(k)
    one_sided = any(r["original"] is None or r["mutant"] is None for r in rows)
    inputs = list(rows[0]["inputs"])
    header = ["step"] + inputs + [f"{k} (orig | mutant)" for k in differing]
    if one_sided:
        header.append("takes the step (orig | mutant)")
    table = [header]
    for i, r in enumerate(rows):
        cells = [str(i)] + [_clip(r["inputs"][k]) for k in inputs]
        for k in differing:
            a = r["original"][k] if r["original"] else "-"
            b = r["mutant"][k] if r["mutant"] else "-"
            cells.append(_clip(a) if a == b else f"{_clip(a)} | {_clip(b)}")
        if one_sided:
            a, b = ("yes" if r[side] is not None else "no" for side in ("original", "mutant"))
            cells.append(a if a == b else f"{a} | {b}")
        table.append(cells)
    widths = [max(len(row[j]) for row in table) for j in range(len(header))]
    for row in table:
        out.write(indent + "  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() + "\n")


def _clip(s: str, width: int = 70) -> str:
    s = " ".join(s.split())
    return s if len(s) <= width else s[:width - 3] + "..."
