"""Proof plans: proofs/<Model>.toml says, per invariant, which engine proves it,
with which k and which strengthening invariants (defined in a companion
proofs/<Model>Proofs.tla that EXTENDS the model).  Format: docs/prove.md."""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, field

from ..tla.errors import Loc, TlaError

ENGINES = ("bmc", "kind", "pdr")


@dataclass
class Step:
    invariant: str
    engine: str = "kind"
    k: int | None = None
    strengthen: list[str] = field(default_factory=list)
    timeout: float | None = None
    note: str = ""


@dataclass
class Plan:
    path: str | None
    module: str | None = None          # the proofs module (strengthening invariants)
    type_invariant: str = "TypeOK"
    steps: dict[str, Step] = field(default_factory=dict)
    notes: dict[str, str] = field(default_factory=dict)   # strengthening name -> why it is needed


def find_plan(model_path: str) -> str | None:
    """proofs/<Model>.toml beside the model's folder, or in the current folder."""
    name = os.path.splitext(os.path.basename(model_path))[0]
    here = os.path.dirname(os.path.abspath(model_path))
    for folder in (os.path.join(here, "proofs"), os.path.join(os.path.dirname(here), "proofs"),
                   os.path.join(os.getcwd(), "proofs")):
        p = os.path.join(folder, name + ".toml")
        if os.path.exists(p):
            return p
    return None


def load_plan(path: str | None) -> Plan:
    if path is None:
        return Plan(None)
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise TlaError("config", f"cannot read the proof plan: {e}", Loc(path, 0, 0)) from None
    folder = os.path.dirname(os.path.abspath(path))
    plan = Plan(path)
    if "module" in data:
        plan.module = os.path.join(folder, data["module"])
    plan.type_invariant = data.get("type_invariant", "TypeOK")
    for name, s in data.get("strengthen", {}).items():
        plan.notes[name] = s.get("note", "") if isinstance(s, dict) else str(s)
    for p in data.get("proof", []):
        if "invariant" not in p:
            raise TlaError("config", "a [[proof]] entry without invariant", Loc(path, 0, 0))
        eng = p.get("engine", "kind")
        if eng not in ENGINES:
            raise TlaError("config", f"unknown engine {eng!r} (one of {', '.join(ENGINES)})", Loc(path, 0, 0))
        plan.steps[p["invariant"]] = Step(p["invariant"], eng, p.get("k"), list(p.get("strengthen", [])),
                                          p.get("timeout"), p.get("note", ""))
    return plan
