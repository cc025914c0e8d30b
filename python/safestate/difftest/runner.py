"""The comparison loop: generate (or read) specs, check each with TLC and with
our checker, count agreements, minimise and save every disagreement."""

from __future__ import annotations

import json
import os
import re
import shutil
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterator

from ..checker.tlc import TlcSummary
from .compare import describe, differences, states_comparable
from .generator import GeneratedSpec, generate
from .minimise import minimise_spec
from .ours import REFUSED, run_ours
from .tlc_batch import TlcBatch


@dataclass
class Tally:
    specs: int = 0
    agree: int = 0
    refused: int = 0
    disagree: int = 0
    timeouts: int = 0
    crashes: int = 0  # our checker raised an internal error (always a defect)
    results: dict[str, int] = field(default_factory=dict)  # TLC's verdicts, for coverage
    disagreements: list[dict] = field(default_factory=list)
    # What the engine refused, by message without its location: what the subset lacks.
    refusals: dict[str, int] = field(default_factory=dict)
    # Grammar 3: per construct, how many specs used it and how each one ended.
    features: dict[str, dict[str, int]] = field(default_factory=dict)

    def count_features(self, features: tuple[str, ...], outcome: str) -> None:
        for f in features:
            row = self.features.setdefault(f, {})
            row[outcome] = row.get(outcome, 0) + 1


Source = Iterator[tuple[str, str, str]]  # (name, tla text or path, cfg text or path)


def refusal_reason(message: str) -> str:
    """The refusal without its file:line:col, so that refusals of one construct count together."""
    first = message.splitlines()[0] if message else "(no message)"
    return re.sub(r"^\S+:\d+:\d+:\s*", "", first)[:160]


def generated(seed: int, count: int, start: int = 0, grammar: int = 2) -> Iterator[GeneratedSpec]:
    for i in range(start, start + count):
        yield generate(seed, i, grammar)


def spec_dir(folder: str) -> list[tuple[str, str, str]]:
    """Every NAME.cfg with a NAME.tla beside it, below `folder`."""
    out = []
    for root, _, files in sorted(os.walk(folder)):
        for f in sorted(files):
            if f.endswith(".cfg") and f[:-4] + ".tla" in files:
                out.append((os.path.join(root, f[:-4]), os.path.join(root, f[:-4] + ".tla"),
                            os.path.join(root, f)))
    return out


class Runner:
    def __init__(self, jar: str | None, out_dir: str | None, minimise: bool, timeout: float,
                 log: Callable[[str], None], engine: str = "python") -> None:
        self.engine = engine
        self.tlc = TlcBatch(jar, timeout) if jar else None
        self.out_dir = out_dir
        self.minimise = minimise
        self.timeout = timeout
        self.log = log
        self.work = tempfile.mkdtemp(prefix="difftest-")
        self.tally = Tally()

    def close(self) -> None:
        if self.tlc:
            self.tlc.close()
        shutil.rmtree(self.work, ignore_errors=True)

    # ------------------------------------------------------------ one spec
    def _write(self, name: str, tla: str, cfg: str) -> tuple[str, str]:
        folder = os.path.join(self.work, name)
        os.makedirs(folder, exist_ok=True)
        tp, cp = os.path.join(folder, name + ".tla"), os.path.join(folder, name + ".cfg")
        Path(tp).write_text(tla)
        Path(cp).write_text(cfg)
        return tp, cp

    def both(self, tla_path: str, cfg_path: str) -> tuple[dict, TlcSummary | None]:
        ours = run_ours(tla_path, cfg_path, self.timeout, self.engine)
        tlc = self.tlc.run(tla_path, cfg_path)[0] if self.tlc else None
        return ours, tlc

    def check(self, name: str, tla_path: str, cfg_path: str, texts: tuple[str, str] | None) -> str:
        """Compares one spec; returns its outcome: agree, refused, timeout, crash,
        disagree, or (without TLC) ours."""
        t = self.tally
        t.specs += 1
        ours, tlc = self.both(tla_path, cfg_path)
        if ours["result"] == "crash":
            t.crashes += 1
        if tlc is None:
            if ours["result"] == REFUSED:
                t.refused += 1
            elif ours["result"] == "timeout":
                t.timeouts += 1
            if ours["result"] == "crash":
                self._record(name, tla_path, cfg_path, texts, ours, None, ["crash"])
            return ours["result"] if ours["result"] in (REFUSED, "timeout", "crash") else "ours"
        t.results[tlc.result] = t.results.get(tlc.result, 0) + 1
        if tlc.result == "timeout" or ours["result"] == "timeout":
            t.timeouts += 1
            return "timeout"
        diffs = differences(ours, tlc, states_comparable(Path(cfg_path).read_text(errors="replace")))
        if ours["result"] == REFUSED:
            t.refused += 1
            why = refusal_reason(ours.get("message") or "")
            t.refusals[why] = t.refusals.get(why, 0) + 1
            return REFUSED
        if not diffs:
            t.agree += 1
            return "agree"
        self._record(name, tla_path, cfg_path, texts, ours, tlc, diffs)
        return "disagree"

    def _record(self, name: str, tla_path: str, cfg_path: str, texts: tuple[str, str] | None,
                ours: dict, tlc: TlcSummary | None, diffs: list[str]) -> None:
        self.tally.disagree += 1
        tla, cfg = texts or (Path(tla_path).read_text(errors="replace"), Path(cfg_path).read_text())
        entry = {"name": name, "fields": diffs,
                 "detail": describe(ours, tlc, diffs) if tlc else ours.get("message", ""),
                 "ours": ours, "tlc": vars(tlc) if tlc else None}
        self.log(f"DISAGREE {name}: {entry['detail']}")
        if self.minimise and texts is not None and tlc is not None:
            small_tla, small_cfg = self._minimise(name, tla, cfg, diffs)
            tp, cp = self._write(name + "_min", small_tla.replace(f"MODULE {name}", f"MODULE {name}_min"),
                                 small_cfg)
            o2, t2 = self.both(tp, cp)
            entry["minimised"] = {"ours": o2, "tlc": vars(t2) if t2 else None,
                                  "lines": len(small_tla.splitlines())}
            tla, cfg = Path(tp).read_text(), small_cfg
            name = name + "_min"
        if self.out_dir:
            os.makedirs(self.out_dir, exist_ok=True)
            Path(self.out_dir, name + ".tla").write_text(tla)
            Path(self.out_dir, name + ".cfg").write_text(cfg)
            Path(self.out_dir, name + ".json").write_text(json.dumps(entry, indent=1) + "\n")
            entry["repro"] = os.path.join(self.out_dir, name + ".tla")
        self.tally.disagreements.append(entry)

    def _minimise(self, name: str, tla: str, cfg: str, diffs: list[str]) -> tuple[str, str]:
        tries = [0]

        def still_fails(t: str, c: str) -> bool:
            tries[0] += 1
            tp, cp = self._write(f"{name}_try", t.replace(f"MODULE {name}", f"MODULE {name}_try"), c)
            ours, tlc = self.both(tp, cp)
            if tlc is None or tlc.result == "timeout" or ours["result"] in ("timeout", REFUSED):
                return False
            if tlc.exit_code in (150, 151, 255) and ours["exit_code"] == tlc.exit_code:
                return False
            return differences(ours, tlc, states_comparable(c)) == diffs
        start = time.monotonic()
        out = minimise_spec(tla, cfg, still_fails)
        self.log(f"  minimised {name}: {len(tla.splitlines())} -> {len(out[0].splitlines())} lines "
                 f"({tries[0]} runs, {time.monotonic() - start:.0f} s)")
        return out

    # ------------------------------------------------------------ loops
    def run_generated(self, seed: int, count: int, start: int, every: int, grammar: int = 2) -> None:
        t0 = time.monotonic()
        for i, g in enumerate(generated(seed, count, start, grammar), 1):
            tp, cp = self._write(g.name, g.tla, g.cfg)
            outcome = self.check(g.name, tp, cp, (g.tla, g.cfg))
            self.tally.count_features(g.features, outcome)
            shutil.rmtree(os.path.dirname(tp), ignore_errors=True)
            if i % every == 0 or i == count:
                self.progress(i, count, t0)

    def run_dir(self, folder: str, every: int) -> None:
        t0 = time.monotonic()
        specs = spec_dir(folder)
        for i, (name, tp, cp) in enumerate(specs, 1):
            self.check(os.path.relpath(name, folder), tp, cp, None)
            if i % every == 0 or i == len(specs):
                self.progress(i, len(specs), t0)

    def progress(self, i: int, n: int, t0: float) -> None:
        t = self.tally
        dt = time.monotonic() - t0
        self.log(f"[difftest] {i}/{n}  agree {t.agree}  refused {t.refused}  disagree {t.disagree}  "
                 f"timeouts {t.timeouts}  crashes {t.crashes}  {dt:.0f} s ({i / max(dt, 1e-9):.1f} specs/s)")


def stderr_log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)
