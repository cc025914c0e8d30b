"""The last mutation result of each registered system, and the justified survivors.

Every `safestate mutate SYSTEM` run writes its summary (the `--json` object) to
`build/mutate/SYSTEM.json` under the repository root (the registry's parent), so that
`safestate systems` and the evidence package (`evidence/model_mutation.py`) show the
last measured score, with when, the sample and the seed it was measured on.

A survivor whose behaviour difference the design page accepts is *justified*: an entry
of the system's manifest

    [[mutate.justified]]
    definition = "C16_Guard"           # the mutated definition
    operator = "drop-conjunct"         # optional: only this operator's mutants
    contains = "TRUE"                  # optional: a substring of the mutated line(s)
    design = "docs/design/x.md#anchor" # the design page's section that says why
    why = "one line: why the difference is acceptable"

names it, and the design anchor must exist (a heading's slug or an explicit id).  A
justified survivor is listed with its justification and is not a gap: the score the
evidence package counts as gaps is over the unjustified survivors (`gaps`).
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import SafestateError


class JustificationError(SafestateError):
    """A `[[mutate.justified]]` entry that cannot be used (names its manifest and entry)."""


@dataclass(frozen=True)
class Justification:
    definition: str
    operator: str | None
    contains: str | None
    design: str          # page#anchor, relative to the repository root
    why: str

    def matches(self, mutant: dict[str, Any]) -> bool:
        return (mutant.get("definition") == self.definition
                and (self.operator is None or mutant.get("operator") == self.operator)
                and (self.contains is None or self.contains in str(mutant.get("replacement", ""))))


def results_path(system: Any) -> Path:
    return Path(system.root) / "build" / "mutate" / f"{system.name}.json"


def write(system: Any, summary: dict[str, Any]) -> Path | None:
    """Stores the run's summary as the system's last result (None: not writable)."""
    path = results_path(system)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(summary) + "\n", encoding="utf-8")
        tmp.replace(path)
    except OSError:
        return None
    return path


def read(system: Any) -> dict[str, Any] | None:
    try:
        d = json.loads(results_path(system).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return d if isinstance(d, dict) else None


def _slug(heading: str) -> str:
    """A heading's anchor as GitHub writes it."""
    s = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return s.replace(" ", "-")


def anchors(page: Path) -> set[str]:
    text = page.read_text(encoding="utf-8")
    out = {_slug(m.group(1)) for m in re.finditer(r"^#+\s+(.+?)\s*#*\s*$", text, re.M)}
    out |= set(re.findall(r"""(?:id|name)\s*=\s*["']([^"']+)["']""", text))
    return out


def justifications(system: Any) -> list[Justification]:
    """The system's `[[mutate.justified]]` entries, each checked: its fields, and that
    its design page and anchor exist."""
    raw = (system.extra.get("mutate") or {}).get("justified", [])
    where = f"{system.manifest}: [[mutate.justified]]"
    if not isinstance(raw, list):
        raise JustificationError(f"{where}: expected an array of tables")
    out = []
    for i, e in enumerate(raw, start=1):
        at = f"{where} entry {i}"
        if not isinstance(e, dict):
            raise JustificationError(f"{at}: expected a table")
        for k in ("definition", "design", "why"):
            if not isinstance(e.get(k), str) or not e[k].strip():
                raise JustificationError(f"{at}: `{k}` must be a non-empty string")
        unknown = sorted(set(e) - {"definition", "operator", "contains", "design", "why"})
        if unknown:
            raise JustificationError(f"{at}: unknown key(s) {', '.join(unknown)} (expected definition, operator, "
                                     f"contains, design, why)")
        page, _, anchor = e["design"].partition("#")
        path = Path(system.root) / page
        if not path.is_file():
            raise JustificationError(f"{at}: design = {e['design']!r}: no such page {path}")
        if not anchor:
            raise JustificationError(f"{at}: design = {e['design']!r}: expected page#anchor (the section that says why)")
        if anchor not in anchors(path):
            raise JustificationError(f"{at}: design = {e['design']!r}: {page} has no anchor #{anchor}")
        out.append(Justification(e["definition"], e.get("operator"), e.get("contains"), e["design"], e["why"]))
    return out


def justify(summary: dict[str, Any], justs: list[Justification]) -> dict[str, Any]:
    """Marks each survivor a justification names (`justified`: its design and why) and
    adds `gaps` (the unjustified survivors) to the summary."""
    gaps = 0
    for m in summary.get("mutants", []):
        if m.get("status") != "survived":
            continue
        j = next((j for j in justs if j.matches(m)), None)
        if j is None:
            m.pop("justified", None)
            gaps += 1
        else:
            m["justified"] = {"design": j.design, "why": j.why}
    summary["gaps"] = gaps
    summary["justified"] = sum(1 for m in summary.get("mutants", []) if m.get("justified"))
    return summary


def one_line(d: dict[str, Any] | None) -> str:
    """The score as `safestate systems` prints it: score, when and on what."""
    if d is None:
        return "not measured"
    c = d.get("counts", {})
    sc = d.get("score")
    what = f"sample of {d.get('classified')} (seed {d.get('seed')})" if d.get("sampled") else "all"
    score = "n/a" if sc is None else f"{100 * sc:.1f}%"
    by_w = c.get("killed_by_witness", 0)
    killed = f"{c.get('killed', 0)} killed" + (f" ({by_w} by a witness)" if by_w else "")
    return (f"{score} ({killed}, {c.get('survived', 0)} survived, {d.get('justified', 0)} "
            f"justified; {what} of {d.get('generated')}; {d.get('when', '?')})")
