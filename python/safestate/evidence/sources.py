"""What the repository says about each requirement, read from its text: the requirement
IDs of REQUIREMENTS.md, the design-page rows, the C++ row definitions, the model's
operators and the tests named after requirement IDs -- each with its file:line."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

# RSM-05, SAF-02, INV-RESET, INV-SAF-EMERGENCY ... as written in REQUIREMENTS.md.
REQ_ID = re.compile(r"\b(?:INV-[A-Z0-9]+(?:-[A-Z0-9]+)*|[A-Z]{3}-\d{2})\b")
# The same IDs as code spells them: RSM05_, RSM-05, rsm05, INV_RESET, INV_NOJOG_AUTO.
_CODE_PREFIX = re.compile(r"(?<![A-Za-z0-9])([A-Za-z]{3})[-_]?(\d{2})(?![0-9])")
_ROW = re.compile(r"^\|\s*([A-Z]{1,2}\d{2})\s*\|")
_DEF = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(\([^)]*\))?\s*==")
_GTEST = re.compile(r"^\s*TEST(?:_F|_P)?\(\s*([A-Za-z0-9_]+)\s*,\s*([A-Za-z0-9_]+)\s*\)")
_PYTEST = re.compile(r"^(\s*)def (test_[A-Za-z0-9_]+)\s*\(")
_PYCLASS = re.compile(r"^class (Test[A-Za-z0-9_]*)")
# Declared links from a test to the requirements it covers (docs/evidence.md):
#   pytest:     @pytest.mark.req("RSM-05", "INV-RESET")   (above the def or the class)
#   GoogleTest: // req: RSM-05 INV-RESET                   (the line(s) just above TEST)
_PYREQ = re.compile(r"^\s*@pytest\.mark\.req\((.*)\)\s*$")
_GTREQ = re.compile(r"^\s*// req:(.*)$")
# "- K17 unreachable by construction: <reason>" on a design page.
_UNREACHABLE = re.compile(r"^- ([A-Z]{1,2}\d{2}) unreachable by construction: (.+)$")
# "- RSM-15 (no design row, no C++ row): <reason>": why a requirement's gap stays open;
# "- HydraulicPressFlat.INV_PRESS (invariant without a mutant): <reason>": an invariant's.
_GAP_REASON = re.compile(r"^- (" + REQ_ID.pattern[2:-2] + r"|[A-Z]\w*\.[A-Za-z_]\w*) \(([^)]*)\): (.+)$")


@dataclass(frozen=True)
class Loc:
    file: str   # relative to the repository root
    line: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}"


@dataclass(frozen=True)
class Requirement:
    id: str
    section: str
    text: str
    loc: Loc


@dataclass(frozen=True)
class DesignRow:
    page: str
    id: str
    text: str
    requirements: tuple[str, ...]
    loc: Loc


@dataclass(frozen=True)
class ModelDef:
    model: str
    name: str
    comment: str
    requirements: tuple[str, ...]
    loc: Loc


@dataclass(frozen=True)
class TestCase:
    kind: str          # "gtest" or "pytest"
    name: str          # Suite.Name (as ctest reports it) or file::[Class::]name (the node id)
    requirements: tuple[str, ...]
    loc: Loc
    declared: tuple[str, ...] = ()   # of `requirements`, those linked by a req marker / comment


@dataclass(frozen=True)
class GapReason:
    """A design page's reason why gaps of a requirement, or of a system's invariant
    (`System.INVARIANT`), stay open (they stay counted)."""
    subject: str
    kinds: tuple[str, ...]
    reason: str
    loc: Loc


@dataclass(frozen=True)
class Unreachable:
    """A design-page row its page declares unreachable by construction, with the reason."""
    page: str
    id: str
    reason: str
    loc: Loc


@dataclass
class Corpus:
    requirements: list[Requirement]
    rows: list[DesignRow] = field(default_factory=list)
    tests: list[TestCase] = field(default_factory=list)
    unreachable: list[Unreachable] = field(default_factory=list)
    gap_reasons: list[GapReason] = field(default_factory=list)


def rel(root: Path, p: Path) -> str:
    try:
        return str(p.resolve().relative_to(root.resolve()))
    except ValueError:
        return str(p)


def read_requirements(path: Path, root: Path) -> list[Requirement]:
    """Each requirement ID in the order REQUIREMENTS.md defines it (a list item that
    starts with the ID), with its section and its text up to the next item."""
    out: list[Requirement] = []
    section = ""
    item: tuple[str, str, int, list[str]] | None = None    # (id, section, line, text lines)

    def close() -> None:
        if item is not None:
            rid, sec, line, text = item
            out.append(Requirement(rid, sec, " ".join(s.strip() for s in text), Loc(rel(root, path), line)))

    lines = path.read_text(encoding="utf-8").splitlines()
    for i, line in enumerate(lines, start=1):
        start = re.match(r"^- (?:Invariant )?(" + REQ_ID.pattern + r")[ :]", line)
        if start or line.startswith(("- ", "#")) or not line.strip():
            close()
            item = (start.group(1), section, i, [line[2:]]) if start else None
            if line.startswith("## "):
                section = line[3:].strip()
        elif item is not None:
            item[3].append(line)
    close()
    # IDs defined inside another item's text ("INV-PRESS: after the motor stops, ...").
    for r in list(out):
        for m in re.finditer(r"(INV-[A-Z0-9]+(?:-[A-Z0-9]+)*): ", r.text):
            out.append(Requirement(m.group(1), r.section, r.text[m.start():], r.loc))
    seen: set[str] = set()
    unique = []
    for r in out:
        if r.id not in seen:
            seen.add(r.id)
            unique.append(r)
    return unique


def code_ids(text: str, known: set[str]) -> tuple[str, ...]:
    """Requirement IDs named in code or prose: RSM-05 / RSM05 / rsm05 / INV_RESET."""
    found: list[str] = []
    for m in REQ_ID.finditer(text):
        found.append(m.group(0))
    for m in _CODE_PREFIX.finditer(text):
        found.append(f"{m.group(1).upper()}-{m.group(2)}")
    # CamelCase in test names: SAF02_InvSafEmergency names INV-SAF-EMERGENCY.
    tokens = {w.lower() for w in re.split(r"[^A-Za-z0-9]+", text) if w}
    found += [rid for rid in known if rid.startswith("INV-") and rid.replace("-", "").lower() in tokens]
    for rid in known:
        # INV_PRESS_AccidentRestart... names INV-PRESS; INV_POWER_OFF (another invariant) does not name INV-POWER.
        pat = r"(?<![A-Za-z0-9])" + rid.replace("-", "[-_]") + r"(?![A-Za-z0-9])(?!_[A-Z]{2})"
        if rid.startswith("INV-") and re.search(pat, text, re.I if text.islower() else 0):
            found.append(rid)
    return tuple(sorted({f for f in found if f in known}))


def design_rows(page: Path, root: Path, known: set[str]) -> list[DesignRow]:
    """Rows of a design page's tables (`| C06 | ... |`); a row that names no requirement
    takes the IDs of the nearest heading above it that does."""
    out: list[DesignRow] = []
    heading_ids: tuple[str, ...] = ()
    for i, line in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
        if line.startswith("#"):
            heading_ids = code_ids(line, known) or heading_ids
            continue
        m = _ROW.match(line)
        if m:
            ids = code_ids(line, known) or heading_ids
            out.append(DesignRow(rel(root, page), m.group(1), line.strip(), ids, Loc(rel(root, page), i)))
    return out


def model_defs(tla: Path, root: Path, known: set[str]) -> list[ModelDef]:
    """Top-level operator definitions with the comment block just above them."""
    out: list[ModelDef] = []
    comment: list[str] = []
    for i, line in enumerate(tla.read_text(encoding="utf-8").splitlines(), start=1):
        s = line.strip()
        if s.startswith("\\*") or s.startswith("(*"):
            comment.append(s.strip("\\*() "))
            continue
        m = _DEF.match(line)
        if m:
            inline = line.split("\\*", 1)[1] if "\\*" in line else ""
            text = " ".join(comment + [inline])
            ids = code_ids(m.group(1) + " " + text, known)
            out.append(ModelDef(tla.stem, m.group(1), text.strip(), ids, Loc(rel(root, tla), i)))
        if not s or m:
            comment = []
    return out


def cpp_row_locations(dirs: list[Path], root: Path) -> dict[str, list[Loc]]:
    """Where each row ID appears as a string literal ("C06") in the C++ sources."""
    out: dict[str, list[Loc]] = {}
    lit = re.compile(r'"([A-Z]{1,2}\d{2})"')
    for d in dirs:
        files = sorted(d.rglob("*")) if d.is_dir() else [d]
        for f in files:
            if f.suffix not in (".hpp", ".cpp", ".h"):
                continue
            for i, line in enumerate(f.read_text(encoding="utf-8").splitlines(), start=1):
                for m in lit.finditer(line):
                    out.setdefault(m.group(1), []).append(Loc(rel(root, f), i))
    return out


class RequirementLinkError(ValueError):
    """A declared link names no requirement of REQUIREMENTS.md, or is malformed."""


def declared_ids(text: str, line: str, known: set[str], where: str) -> tuple[str, ...]:
    """The IDs of a req marker's arguments or a `// req:` comment (`text`, part of the
    source `line` at `where` = file:line): each must be a requirement ID of
    REQUIREMENTS.md, written as it spells it; the error names the column of the first bad one."""
    ids = re.findall(r"[A-Za-z0-9_-]+", text.replace('"', " ").replace("'", " ").replace(",", " "))
    if not ids:
        raise RequirementLinkError(f"{where}:{line.index(text) + 1}: expected requirement IDs (e.g. RSM-05) "
                                   "after the req marker, found none")
    bad = [x for x in ids if x not in known]
    if bad:
        col = line.index(bad[0], line.index(text)) + 1
        raise RequirementLinkError(f"{where}:{col}: {', '.join(bad)}: not a requirement ID of REQUIREMENTS.md "
                                   "(expected e.g. RSM-05, INV-RESET)")
    return tuple(ids)


def _link(kind: str, name: str, named: tuple[str, ...], declared: tuple[str, ...], loc: Loc) -> TestCase:
    return TestCase(kind, name, tuple(sorted(set(named) | set(declared))), loc, declared)


def gtests(folder: Path, root: Path, known: set[str]) -> list[TestCase]:
    out = []
    for f in sorted(folder.rglob("*.cpp")):
        pending: list[str] = []
        for i, line in enumerate(f.read_text(encoding="utf-8").splitlines(), start=1):
            r = _GTREQ.match(line)
            if r:
                pending += declared_ids(r.group(1), line, known, f"{rel(root, f)}:{i}")
                continue
            m = _GTEST.match(line)
            if m:
                name = f"{m.group(1)}.{m.group(2)}"
                out.append(_link("gtest", name, code_ids(m.group(1) + " " + m.group(2), known), tuple(pending),
                                 Loc(rel(root, f), i)))
            if not line.lstrip().startswith("//"):
                pending = []    # a `// req:` line binds to the TEST right below its comment block
    return out


def pytests(folder: Path, root: Path, known: set[str]) -> list[TestCase]:
    out = []
    for f in sorted(folder.glob("test_*.py")):
        cls = None
        cls_ids: tuple[str, ...] = ()
        pending: list[str] = []
        for i, line in enumerate(f.read_text(encoding="utf-8").splitlines(), start=1):
            r = _PYREQ.match(line)
            if r:
                pending += declared_ids(r.group(1), line, known, f"{rel(root, f)}:{i}")
                continue
            if line.lstrip().startswith("@pytest.mark.req"):
                raise RequirementLinkError(f"{rel(root, f)}:{i}:{line.index('pytest.mark.req') + 1}: expected "
                                           '@pytest.mark.req("ID", ...) on one line, above a test or a test class')
            c = _PYCLASS.match(line)
            if c:
                cls, cls_ids, pending = c.group(1), tuple(pending), []
                continue
            if line and not line[0].isspace() and not line.startswith(("def ", "@", "#", ")")):
                cls = None if not line.startswith("class ") else cls
            m = _PYTEST.match(line)
            if m:
                inner = bool(m.group(1)) and cls is not None
                node = f"{rel(root, f)}::{cls}::{m.group(2)}" if inner else f"{rel(root, f)}::{m.group(2)}"
                if m.group(1) and not inner:
                    continue  # a nested helper, not a test
                declared = (cls_ids if inner else ()) + tuple(pending)
                out.append(_link("pytest", node, code_ids(m.group(2), known), declared, Loc(rel(root, f), i)))
                pending = []
            elif line and not line[0].isspace() and not line.startswith(("@", ")", "#")):
                pending = []    # markers bind to the def or class right below them
    return out


def unreachable_rows(page: Path, root: Path) -> list[Unreachable]:
    """The rows a design page declares unreachable by construction, each with its reason."""
    out = []
    for i, line in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
        m = _UNREACHABLE.match(line)
        if m:
            out.append(Unreachable(rel(root, page), m.group(1), m.group(2).strip(), Loc(rel(root, page), i)))
    return out


def gap_reasons(page: Path, root: Path, known: set[str], kinds: set[str],
                invariant_kinds: frozenset[str] = frozenset()) -> list[GapReason]:
    """The `- ID (kind, kind): reason` items of a design page (ID: a requirement, with one of
    `kinds`, or `System.INVARIANT`, with one of `invariant_kinds`); an unknown ID or kind is
    a located error (a reason that explains nothing would pass unnoticed)."""
    out = []
    for i, line in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
        m = _GAP_REASON.match(line)
        if not m:
            continue
        where = f"{rel(root, page)}:{i}"
        of_invariant = "." in m.group(1)
        if not of_invariant and m.group(1) not in known:
            raise RequirementLinkError(f"{where}:3: {m.group(1)}: not a requirement ID of REQUIREMENTS.md")
        allowed = invariant_kinds if of_invariant else kinds
        named = tuple(k.strip() for k in m.group(2).split(","))
        bad = [k for k in named if k not in allowed]
        if bad:
            raise RequirementLinkError(f"{where}:{line.index('(') + 2}: {', '.join(bad)}: not a gap kind (expected "
                                       f"one of: {', '.join(sorted(allowed))})")
        out.append(GapReason(m.group(1), named, m.group(3).strip(), Loc(rel(root, page), i)))
    return out
