"""Model mutants written as patches (models/mutants/<Model>.toml), and model variants
that check one invariant (a mutant's target, or a reachability witness `Witness_X`).
The one implementation behind the mutant tests of every registered system
(`systems/<Name>/system.toml` names its mutant file: `mutants = "..."`).

A mutant is a list of exact text substitutions against the model's own files (the
.tla, or its .cfg) plus the invariant that must catch it. `materialise` copies the
model's folder into a fresh directory, applies the substitutions and writes a .cfg
that checks only the target invariant, so a mutant can never go stale: if the
original text is no longer found exactly once, `MutationError` says which mutant,
which file and what was looked for.

    [[mutant]]
    name = "estop_in_motion_cat1_ramp"
    requirement = "RSM-03"
    invariant = "RSM03_ESTOP_CAT0"
    expect = "violated"        # or "holds": the invariant is a witness the mutant loses
    trace_length = 6           # TLC's, for "violated" (optional: not yet recorded)
    distinct_states = 1234     # TLC's distinct states at the violation (or in all, "holds")
    why = "..."
    [[mutant.patch]]
    file = "SystemStateManager.tla"
    original = '...'
    replacement = '...'
"""

from __future__ import annotations

import re
import shutil
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from .errors import SafestateError

if TYPE_CHECKING:
    from .systems.registry import System

# Keywords that open a section of a TLC .cfg file.
_CFG_KEYWORDS = {"CONSTANT", "CONSTANTS", "INIT", "NEXT", "SPECIFICATION", "INVARIANT", "INVARIANTS",
                 "PROPERTY", "PROPERTIES", "VIEW", "SYMMETRY", "CONSTRAINT", "CONSTRAINTS",
                 "ACTION_CONSTRAINT", "ACTION_CONSTRAINTS", "CHECK_DEADLOCK", "ALIAS", "POSTCONDITION"}


class MutationError(SafestateError):
    """A mutant that no longer applies, or a malformed mutant file."""


@dataclass(frozen=True)
class Patch:
    file: str
    original: str
    replacement: str


@dataclass(frozen=True)
class Mutant:
    model: str              # module name, e.g. "SystemStateManager"
    name: str
    requirement: str
    invariant: str
    expect: str             # "violated" or "holds"
    trace_length: int | None     # TLC's; None: not recorded yet (the kill is still checked)
    distinct_states: int | None  # likewise
    why: str
    patches: tuple[Patch, ...]

    @property
    def id(self) -> str:
        return f"{self.model}:{self.name}"


def load(path: Path) -> list[Mutant]:
    """The mutants of one model's TOML file (named after the model)."""
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as e:
        raise MutationError(f"{path}: {e}") from e
    model = path.stem
    out: list[Mutant] = []
    for i, m in enumerate(data.get("mutant", [])):
        where = f"{path}: mutant #{i + 1}"
        try:
            if "patch" in m:
                patches = tuple(Patch(p["file"], p["original"], p["replacement"]) for p in m["patch"])
            else:  # the flat form of models/mutants/SafetyService.toml: one patch, `target`
                patches = (Patch(Path(m["file"]).name, m["original"], m["replacement"]),)
            expect = m.get("expect", "violated")
            if expect not in ("violated", "holds"):
                raise MutationError(f"{where}: expect must be 'violated' or 'holds', not {expect!r}")
            invariant = m["invariant"] if "invariant" in m else m["target"]
            out.append(Mutant(model, m["name"], m.get("requirement", ""), invariant, expect,
                              m.get("trace_length"), m.get("distinct_states"), m.get("why", ""), patches))
        except KeyError as e:
            raise MutationError(f"{where}: missing key {e}") from e
    names = [m.name for m in out]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        raise MutationError(f"{path}: duplicate mutant names {sorted(dup)}")
    return out


def load_all(folder: Path) -> list[Mutant]:
    return [m for p in sorted(folder.glob("*.toml")) for m in load(p)]


def of_system(system: System) -> list[Mutant]:
    """The mutants the system's manifest names (none when it names no file)."""
    if system.mutants is None:
        return []
    if not system.mutants.is_file():
        raise MutationError(f"{system.manifest}: mutants file {system.mutants} does not exist")
    return load(system.mutants)


def witnesses(model: Path) -> list[str]:
    """The model's reachability witnesses: its `Witness_X ==` operators, in order."""
    return re.findall(r"^(Witness_\w+)\s+==", model.read_text(encoding="utf-8"), re.M)


def apply_patch(text: str, patch: Patch, who: str) -> str:
    n = text.count(patch.original)
    if n != 1:
        raise MutationError(f"{who}: original text of {patch.file} found {n} times, expected once: "
                            f"{patch.original.strip()[:80]!r}")
    return text.replace(patch.original, patch.replacement)


def only_invariant(cfg_text: str, invariant: str) -> str:
    """The .cfg with its INVARIANT(S) sections replaced by the one invariant."""
    out: list[str] = []
    skipping = False
    for line in cfg_text.splitlines():
        words = line.split()
        head = words[0] if words else ""
        if head in _CFG_KEYWORDS:
            skipping = head in ("INVARIANT", "INVARIANTS")
        if not skipping:
            out.append(line)
    out.append(f"INVARIANT {invariant}")
    return "\n".join(out) + "\n"


def variant(model: Path, invariant: str, dest: Path, patches: tuple[Patch, ...] = (),
            who: str = "") -> Path:
    """Writes every module and cfg of the model's folder into `dest`, `patches` applied,
    with the model's .cfg checking only `invariant`; returns the copy of the model."""
    dest.mkdir(parents=True, exist_ok=True)
    for f in model.parent.iterdir():
        if f.is_file() and f.suffix in (".tla", ".cfg"):
            shutil.copyfile(f, dest / f.name)
    for patch in patches:
        target = dest / patch.file
        if not target.is_file():
            raise MutationError(f"{who}: no file {patch.file} in {model.parent}")
        target.write_text(apply_patch(target.read_text(encoding="utf-8"), patch, who), encoding="utf-8")
    cfg = dest / model.with_suffix(".cfg").name
    cfg.write_text(only_invariant(cfg.read_text(encoding="utf-8"), invariant), encoding="utf-8")
    return dest / model.name


def materialise(mutant: Mutant, models: Path, dest: Path) -> Path:
    """Writes the mutant (every file of `models`, patched) into `dest`; returns its .tla."""
    return variant(models / f"{mutant.model}.tla", mutant.invariant, dest, mutant.patches, mutant.id)
