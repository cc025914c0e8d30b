"""Shared by the model tests: a model's declared mutants (models/mutants/<Model>.toml),
its reachability witnesses (`Witness_X ==`), and one check of a model variant with one
invariant listed."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

from conftest import REPO, run_safestate


def mutants_of(model: str) -> list[dict]:
    """The mutants declared for models/<model>.tla."""
    return tomllib.loads((REPO / "models" / "mutants" / f"{model}.toml").read_text())["mutant"]


def witnesses_of(model: Path) -> list[str]:
    return sorted(set(re.findall(r"^(Witness_\w+) ==", model.read_text(), re.M)))


def cfg_with_only(model: Path, invariant: str) -> str:
    """The model's .cfg (constants, INIT, NEXT, VIEW) with one invariant listed."""
    head = model.with_suffix(".cfg").read_text().split("INVARIANTS")[0]
    return f"{head}INVARIANTS\n    {invariant}\n"


def check_variant(folder: Path, model: Path, invariant: str,
                  replaced: dict[str, str] | None = None) -> dict:
    """`safestate check --json` of `model` in `folder` with only `invariant` listed;
    `replaced` maps a module file name of the models folder to its variant text."""
    for name, text in (replaced or {}).items():
        (folder / name).write_text(text)
    if model.name not in (replaced or {}):
        (folder / model.name).write_text(model.read_text())
    (folder / model.with_suffix(".cfg").name).write_text(cfg_with_only(model, invariant))
    proc = run_safestate("check", str(folder / model.name), "--json")
    assert "Traceback" not in proc.stderr, proc.stderr
    return json.loads(proc.stdout)


def mutated_source(mutant: dict) -> str:
    """The mutant's file with its original text (which must occur once) replaced."""
    source = (REPO / mutant["file"]).read_text()
    assert source.count(mutant["original"]) == 1, "the original text must occur exactly once"
    return source.replace(mutant["original"], mutant["replacement"])
