"""`--max-memory` is honoured while the initial states are computed (issue 10): an
Init that enumerates a huge set stops with the limit named and exit code 153, and
progress lines appear before the first state exists."""

from __future__ import annotations

from pathlib import Path

from safestate.checker import exit_codes
from safestate.checker.explore import Explorer
from safestate.checker.model import load_model
from safestate.cli import main
from safestate.tla.enum_watch import rss_mb

HUGE_INIT = """---- MODULE HugeInit ----
EXTENDS Naturals
VARIABLE x
Init == x \\in SUBSET (1..40)
Next == UNCHANGED x
====
"""

# Headroom above the test process's own memory: reached after ~2 s of enumeration.
HEADROOM_MB = 40


def _spec(tmp_path: Path) -> Path:
    tla = tmp_path / "HugeInit.tla"
    tla.write_text(HUGE_INIT)
    (tmp_path / "HugeInit.cfg").write_text("INIT Init\nNEXT Next\n")
    return tla


def test_memory_limit_stops_the_enumeration_of_initial_states(tmp_path: Path) -> None:
    lines: list[str] = []
    limit = int(rss_mb()) + HEADROOM_MB
    explorer = Explorer(load_model(str(_spec(tmp_path))), False, limit, lines.append)
    r = explorer.run()
    assert r.result == "error" and r.error is not None and r.error.kind == "memory"
    assert r.error.message.startswith(f"memory limit of {limit} MB exceeded while computing the initial "
                                      f"states (enumerating SUBSET 1..40: ")
    assert r.distinct_states == 0
    assert lines[0] == "Computing initial states..."


def test_check_over_the_memory_limit_in_init_exits_153(tmp_path: Path, capsys) -> None:
    limit = int(rss_mb()) + HEADROOM_MB
    code = main(["check", str(_spec(tmp_path)), "--max-memory", str(limit)])
    assert code == exit_codes.ERROR_SYSTEM == 153
    out = capsys.readouterr()
    assert f"memory limit of {limit} MB exceeded while computing the initial states" in out.out + out.err


def test_initial_states_are_announced_and_counted(tmp_path: Path) -> None:
    tla = tmp_path / "Small.tla"
    tla.write_text(HUGE_INIT.replace("HugeInit", "Small").replace("1..40", "1..3"))
    (tmp_path / "Small.cfg").write_text("INIT Init\nNEXT Next\n")
    lines: list[str] = []
    r = Explorer(load_model(str(tla)), False, None, lines.append).run()
    assert r.result == "success" and r.distinct_states == 8
    assert lines[:2] == ["Computing initial states...", "Finished computing initial states: 8 distinct "
                                                        "states generated."]
