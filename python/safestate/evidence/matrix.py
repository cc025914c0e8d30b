"""The traceability matrix: every requirement ID of REQUIREMENTS.md to its design-page
rows, C++ rows, model operators and invariants, check / proof / conformance results,
tests and source locations -- and the gaps, counted, never dropped."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .sources import Corpus, DesignRow, GapReason, Loc, ModelDef, Requirement, TestCase, Unreachable

from .steps import SystemRuns

# The gaps of one requirement that a design page may explain (sources.gap_reasons).
REQUIREMENT_GAP_KINDS = {"no invariant", "no conformance", "no design row", "no C++ row", "no model operator",
                         "no test"}
# ... and those of a system's invariant (`- System.INVARIANT (kind): reason`).
INVARIANT_GAP_KINDS = frozenset({"invariant without a mutant", "invariant names no requirement"})


@dataclass(frozen=True)
class Gap:
    kind: str        # "no test", "test failed", "not modelled", "invariant without a mutant", ...
    subject: str     # the requirement, invariant or row
    detail: str


@dataclass
class CppRow:
    system: str
    id: str
    locs: list[Loc]
    taken: bool | None      # None: the system has no conformance run


@dataclass
class Invariant:
    system: str
    name: str
    loc: Loc | None
    check: str              # the system's check result for its cfg
    check_ok: bool          # as the manifest expects (a defective reference: its violation)
    proof: dict[str, Any] | None
    mutants: list[str]      # killing mutants' names
    expected_violated: bool = False   # a defective reference's invariant, violated by design

    @property
    def refuted_as_expected(self) -> bool:
        """A defective reference's expected violation, found by the check and by BMC."""
        return self.expected_violated and self.check_ok and self.proof is not None and \
            self.proof.get("status") == "violated"


@dataclass
class Entry:
    req: Requirement
    systems: list[str] = field(default_factory=list)
    rows: list[DesignRow] = field(default_factory=list)
    cpp_rows: list[CppRow] = field(default_factory=list)
    operators: list[ModelDef] = field(default_factory=list)
    invariants: list[Invariant] = field(default_factory=list)
    conformance: dict[str, dict[str, Any]] = field(default_factory=dict)
    tests: list[tuple[TestCase, str]] = field(default_factory=list)    # (test, outcome)
    gaps: list[Gap] = field(default_factory=list)
    outside: list[str] = field(default_factory=list)   # registered systems not in this package


@dataclass
class SystemFacts:
    """What the matrix needs of one system besides its runs."""
    runs: SystemRuns
    defs: list[ModelDef]
    invariants: list[str]
    cpp_rows: dict[str, list[Loc]]


@dataclass(frozen=True)
class UnreachableRow:
    """A row never exercised because it cannot fire: not a gap, shown with its reason (the
    design page) and the argument that it indeed never fires (the conformance run)."""
    system: str
    why: Unreachable
    argument: str


@dataclass
class Matrix:
    entries: list[Entry]
    gaps: list[Gap]           # every gap once (requirement, invariant and row gaps)
    unreachable: list[UnreachableRow] = field(default_factory=list)


def check_verdict(runs: SystemRuns) -> str:
    j = runs.check.json()
    verdict = str(j.get("result")) if isinstance(j, dict) else f"exit {runs.check.returncode}"
    expected = runs.system.expected_violation
    if expected is not None and isinstance(j, dict):
        got = j.get("violated")
        return f"{got} violated as expected (defective reference)" if got == expected else \
            f"{verdict}, expected {expected} violated (defective reference)"
    return verdict


def check_ok(runs: SystemRuns) -> bool:
    """The check did what the system's manifest expects: pass, or (a defective reference)
    violate exactly its expected invariant."""
    expected = runs.system.expected_violation
    if expected is None:
        return check_verdict(runs) == "success"
    j = runs.check.json()
    return isinstance(j, dict) and j.get("violated") == expected and runs.check.returncode == 12


def proofs_by_invariant(runs: SystemRuns) -> dict[str, dict[str, Any]]:
    j = runs.prove.json() if runs.prove else None
    return {r["invariant"]: r for r in j.get("results", [])} if isinstance(j, dict) else {}


def conform_summary(runs: SystemRuns) -> dict[str, Any] | None:
    j = runs.conform.json() if runs.conform else None
    return j if isinstance(j, dict) else None


def build(corpus: Corpus, facts: list[SystemFacts], test_results: dict[str, str],
          elsewhere: dict[str, list[str]]) -> Matrix:
    """`elsewhere`: requirement -> registered systems left out of this package (built
    with --system): such a requirement is listed, marked as not in the package, and
    its missing chain is not counted as gaps."""
    by_name = {f.runs.system.name: f for f in facts}
    gaps: list[Gap] = []
    entries = []
    for req in corpus.requirements:
        e = Entry(req)
        for f in facts:
            sys_ = f.runs.system
            owns = req.id in sys_.requirements or any(req.id in d.requirements for d in f.defs if d.name in f.invariants)
            if owns:
                e.systems.append(sys_.name)
        if not e.systems and elsewhere.get(req.id):
            e.outside = elsewhere[req.id]
            entries.append(e)
            continue
        e.rows = [r for r in corpus.rows if req.id in r.requirements]
        e.tests = [(t, test_results.get(t.name, "not run")) for t in corpus.tests if req.id in t.requirements]
        for name in e.systems:
            _fill_system(e, by_name[name])
        e.gaps = _explained(_requirement_gaps(e), corpus.gap_reasons)
        gaps += e.gaps
        entries.append(e)
    here = {e.req.id for e in entries if not e.outside}
    gaps += _stale_reasons([r for r in corpus.gap_reasons if r.subject in here], gaps)
    row_gaps, unreachable = _row_gaps(corpus, facts)
    invariant_gaps = _explained(_invariant_gaps(facts), corpus.gap_reasons)
    systems = {f.runs.system.name for f in facts}
    gaps += invariant_gaps + _stale_reasons(
        [r for r in corpus.gap_reasons if r.subject.split(".")[0] in systems], invariant_gaps) + row_gaps
    return Matrix(entries, gaps, unreachable)


def _fill_system(e: Entry, f: SystemFacts) -> None:
    runs = f.runs
    proofs = proofs_by_invariant(runs)
    verdict = check_verdict(runs)
    conf = conform_summary(runs)
    taken = set(conf.get("rows_taken", [])) if conf else None
    only = runs.system.requirements[0] if len(runs.system.requirements) == 1 else None
    for d in f.defs:
        if e.req.id not in d.requirements and not (d.name in f.invariants and not d.requirements and only == e.req.id):
            continue
        if d.name in f.invariants:
            killers = [m.mutant.name for m in runs.mutants if m.killed and m.mutant.invariant == d.name]
            e.invariants.append(Invariant(runs.system.name, d.name, d.loc, verdict, check_ok(runs),
                                              proofs.get(d.name), killers,
                                              d.name == runs.system.expected_violation))
        else:
            e.operators.append(d)
    page = str(runs.system.design.relative_to(runs.system.root))
    for r in e.rows:
        if r.page == page and r.id in f.cpp_rows:
            e.cpp_rows.append(CppRow(runs.system.name, r.id, f.cpp_rows[r.id], None if taken is None else r.id in taken))
    if conf is not None:
        e.conformance[runs.system.name] = conf


def _requirement_gaps(e: Entry) -> list[Gap]:
    rid = e.req.id
    out = []
    if not e.systems:
        out.append(Gap("not in a registered system", rid, "no system of systems/ lists it and no registered model "
                       "has an invariant named after it: not model-checked, proved or conformance-tested"))
    elif not e.invariants:
        out.append(Gap("no invariant", rid, "no invariant of the CI cfg names this requirement"))
    elif not e.conformance:
        out.append(Gap("no conformance", rid, f"{', '.join(e.systems)}: no C++ binding and adapter: the C++ is not "
                       "run against the model"))
    if not e.rows:
        out.append(Gap("no design row", rid, "no row of a design-page table (| ID | ...) names it"))
    if not e.cpp_rows:
        out.append(Gap("no C++ row", rid, "no C++ table row of its system(s) names one of its design rows (a string literal such "
                       "as \"C06\" in the system's cpp_sources)"))
    if e.systems and not e.operators and not e.invariants:
        out.append(Gap("no model operator", rid, "no operator of the model names it"))
    if not e.tests:
        out.append(Gap("no test", rid, "no GoogleTest or pytest test is named after it"))
    for t, outcome in e.tests:
        if outcome in ("failed", "not run"):
            out.append(Gap(f"test {outcome}", rid, f"{t.name} ({t.loc})"))
    for inv in e.invariants:
        if not inv.check_ok:
            out.append(Gap("model check failed", rid, f"{inv.system}: {inv.check}"))
        if inv.refuted_as_expected:
            continue
        if inv.proof is None:
            out.append(Gap("not proved", rid, f"{inv.system}.{inv.name}: no proof run"))
        elif inv.proof.get("status") != "proved":
            out.append(Gap("not proved", rid, f"{inv.system}.{inv.name}: {inv.proof.get('status')}"))
    for name, conf in e.conformance.items():
        if conf.get("mismatches"):
            out.append(Gap("conformance mismatch", rid, f"{name}: {conf.get('first_mismatch')}"))
    return out


def _explained(gaps: list[Gap], reasons: list[GapReason]) -> list[Gap]:
    """A gap a design page explains keeps its kind (it stays counted), with the reason."""
    why = {(r.subject, k): r for r in reasons for k in r.kinds}
    return [Gap(g.kind, g.subject, f"{why[g.subject, g.kind].reason} ({why[g.subject, g.kind].loc})")
            if (g.subject, g.kind) in why else g for g in gaps]


def _stale_reasons(reasons: list[GapReason], gaps: list[Gap]) -> list[Gap]:
    """A reason for a gap that is not there any more is itself shown (the page is out of date)."""
    open_ = {(g.subject, g.kind) for g in gaps}
    return [Gap("stale gap reason", r.subject, f"{r.loc} explains '{k}', which is not a gap of it")
            for r in reasons for k in r.kinds if (r.subject, k) not in open_]


def _invariant_gaps(facts: list[SystemFacts]) -> list[Gap]:
    out = []
    for f in facts:
        runs = f.runs
        for inv in f.invariants:
            killers = [m for m in runs.mutants if m.mutant.invariant == inv]
            if not any(m.killed for m in killers):
                why = "a mutant targets it but survives" if killers else "no model mutant targets it"
                out.append(Gap("invariant without a mutant", f"{runs.system.name}.{inv}", why))
            if len(runs.system.requirements) != 1 and not any(inv == d.name and d.requirements for d in f.defs):
                out.append(Gap("invariant names no requirement", f"{runs.system.name}.{inv}",
                               "neither its name nor the comment above it names a requirement ID"))
        for m in runs.mutants:
            if not m.killed:
                out.append(Gap("mutant survives", f"{runs.system.name}:{m.mutant.name}",
                               f"{m.mutant.invariant} ({m.mutant.expect}) not caught: exit {m.step.returncode}"))
        if runs.mutant_error:
            out.append(Gap("mutant does not apply", runs.system.name, runs.mutant_error))
    return out


def unreachable_argument(system: str, conf: dict[str, Any]) -> str:
    """Why a row the conformance declares unreachable indeed never fires (CI cfg)."""
    ic = conf.get("input_complete") or {}
    probes = (f"; the input-complete pass fed every one of its {ic['states']:,} reachable states "
              f"{ic['probes']:,} input probes" if isinstance(ic, dict) and "states" in ic else "")
    return (f"{system}: the conformance replayed {conf.get('transitions_covered', 0):,} of "
            f"{conf.get('transitions_total', 0):,} reachable transitions of the CI model{probes}; the row fired "
            "neither in the model (RowsFiredBy) nor in the C++, and `safestate conform` fails if a row declared "
            f"unreachable fires (fired: {', '.join(conf.get('rows_unreachable_fired', [])) or 'none'})")


def _row_gaps(corpus: Corpus, facts: list[SystemFacts]) -> tuple[list[Gap], list[UnreachableRow]]:
    """A design-page row is exercised when a system with conformance and that design
    page fired it; a row its conformance declares unreachable (and never saw fire) is
    shown apart with the page's reason, a gap only when the page gives none; every
    other row of a page of a packaged system is a gap."""
    pages = {str(f.runs.system.design.relative_to(f.runs.system.root)): f for f in facts}
    taken: dict[str, set[str]] = {}
    unreachable: dict[str, dict[str, str]] = {}     # page -> row -> the argument
    conformed: set[str] = set()
    for f in facts:
        conf = conform_summary(f.runs)
        page = str(f.runs.system.design.relative_to(f.runs.system.root))
        if conf is not None:
            conformed.add(page)
            taken.setdefault(page, set()).update(conf.get("rows_taken", []))
            arg = unreachable_argument(f.runs.system.name, conf)
            unreachable.setdefault(page, {}).update({r: arg for r in conf.get("rows_unreachable", [])})
    reasons = {(u.page, u.id): u for u in corpus.unreachable}
    ids: dict[str, set[str]] = {}
    for f in facts:
        page = str(f.runs.system.design.relative_to(f.runs.system.root))
        ids.setdefault(page, set()).update(f.runs.system.requirements)
        ids[page].update(r for d in f.defs if d.name in f.invariants for r in d.requirements)
    out: list[Gap] = []
    shown: list[UnreachableRow] = []
    for r in corpus.rows:
        if r.page not in pages or not set(r.requirements) & ids[r.page]:
            continue   # another system's row (a shared design page)
        subject = f"{r.page} {r.id}"
        if r.page not in conformed:
            out.append(Gap("row never exercised", subject, "no system with this design page has "
                           "conformance: the C++ of this row is not run against the model"))
        elif r.id in taken.get(r.page, set()):
            if (r.page, r.id) in reasons:
                out.append(Gap("declared unreachable but fired", subject, f"{reasons[r.page, r.id].loc} says it "
                               "cannot fire, the conformance fired it"))
        elif r.id in unreachable.get(r.page, {}):
            why = reasons.get((r.page, r.id))
            if why is None:
                out.append(Gap("unreachable row without a reason", subject, "the conformance declares it "
                               "unreachable by construction and it never fired, but the design page gives no "
                               f"'- {r.id} unreachable by construction: <reason>' item"))
            else:
                shown.append(UnreachableRow(pages[r.page].runs.system.name, why, unreachable[r.page][r.id]))
        else:
            out.append(Gap("row never exercised", subject, "conformance never fired it"))
    return out, shown
