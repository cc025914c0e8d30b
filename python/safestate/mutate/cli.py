"""``safestate mutate SYSTEM|MODEL.tla``: the mutation score of a model's properties.

Generates the first-order mutants of the model's behaviour definitions (see
docs/mutate.md for the operators), checks each with the model's CI cfg and reports
the score killed / (killed + survived).  A survivor changes the observable behaviour
(system.toml `[mutate] observables`, driven by the same `inputs`) and no property
notices: its shortest difference trace is printed.  Equivalent, timed-out and erroneous
mutants are listed, never counted.

exit codes of mutate: 0 it ran (score printed); 2 usage or input error (unknown
system or operator, a model that does not check, no inputs/observables declared);
3 the score is below --min-score; 255 internal error.
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import time
from pathlib import Path
from typing import Any

from ..errors import SafestateError, closed_stdout_exit, one_line
from ..tla.errors import TlaError
from .cache import Cache, OriginalRecord
from .classify import Outcome, Subject, classify_all, materialise, prepare
from .generate import Mutant, dedupe, generate
from .operators import OPERATORS
from .product import Projection
from . import results
from .report import score, summary, write_text
from .witness import WitnessSet

USAGE = 2
BELOW_MIN_SCORE = 3
INTERNAL = 255


class InputError(SafestateError):
    """An argument or input file `mutate` cannot use."""


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("target", help="a registered system (safestate systems) or its model .tla")
    p.add_argument("--config", help="the .cfg (default: the system's ci_config, or MODEL.cfg)")
    p.add_argument("--screen-config", metavar="CFG",
                   help="check every mutant on this cfg first, a kill there is final (default: the system's "
                   "[mutate] screen_config, when --config is its ci_config)")
    p.add_argument("--no-screen", action="store_true", help="no screening cfg: every mutant on the CI cfg only")
    p.add_argument("--inputs", help="comma-separated input variables (default: system.toml [mutate] inputs)")
    p.add_argument("--observables", help="comma-separated observable variables (default: system.toml "
                   "[mutate] observables)")
    p.add_argument("--operator", action="append", metavar="NAME", choices=sorted(OPERATORS),
                   help="only this operator (repeatable): " + ", ".join(OPERATORS))
    p.add_argument("--only", action="append", metavar="TEXT",
                   help="only the mutants whose id contains TEXT (repeatable), e.g. unchanged@Cycle:700")
    p.add_argument("--sample", type=int, metavar="N", help="classify a sample of N mutants, stratified by operator")
    p.add_argument("--seed", type=int, default=0, help="the sample's seed (default 0)")
    p.add_argument("--workers", type=int, default=2, help="mutants classified at once (default 2)")
    p.add_argument("--timeout", type=float, default=300.0, metavar="S", help="CPU seconds per mutant, check and search (default 300)")
    p.add_argument("--engine", choices=("auto", "native", "python"), default="auto",
                   help="the check's engine (default auto: the native core where it accepts the model)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.add_argument("--itf-dir", metavar="DIR", help="write each survivor's difference trace as ITF JSON there")
    p.add_argument("--list", action="store_true", help="only list the generated mutants (models/mutants form)")
    p.add_argument("--no-cache", action="store_true", help="neither read nor write the outcome cache")
    p.add_argument("--min-score", type=float, metavar="P", help="exit 3 when the score (0..1) is below P")


def _terminate(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt  # the workers are ended in classify_all's cleanup


def run(args: argparse.Namespace) -> int:
    import signal
    signal.signal(signal.SIGTERM, _terminate)
    try:
        return _run(args)
    except (InputError, SafestateError, TlaError) as e:
        msg = (f"{e.loc}: " if isinstance(e, TlaError) and e.loc else "") + (
            e.message if isinstance(e, TlaError) else one_line(e))
        if args.json:
            print(json.dumps({"result": "error", "error": msg}))
        print(f"error: {msg}", file=sys.stderr)
        return USAGE
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return closed_stdout_exit()
    except Exception as e:  # noqa: BLE001 - the boundary: never a traceback
        print(f"internal error: {type(e).__name__}: {e}", file=sys.stderr)
        return INTERNAL


def _resolve(args: argparse.Namespace) -> tuple[Any, str, Path, Path, Projection, Path | None]:
    from ..systems.registry import find, for_model
    system = None
    if args.target.endswith(".tla"):
        model = Path(args.target)
        if not model.is_file():
            raise InputError(f"{model}: no such model file")
        system = for_model(str(model))
    else:
        system = find(args.target)
        if system is None:
            raise InputError(f"{args.target}: not a registered system (safestate systems) and not a .tla file")
        model = system.model
    cfg = Path(args.config) if args.config else (system.ci_config if system else model.with_suffix(".cfg"))
    if not cfg.is_file():
        raise InputError(f"{cfg}: no such cfg file")
    decl: dict[str, Any] = dict(system.extra.get("mutate", {})) if system else {}
    where = f"{system.manifest} [mutate]" if system else "--inputs/--observables"
    inputs = args.inputs.split(",") if args.inputs else decl.get("inputs")
    observables = args.observables.split(",") if args.observables else decl.get("observables")
    if not inputs or not observables:
        raise InputError(f"{where}: inputs and observables must be declared (lists of model variables; "
                         f"docs/adding-a-system.md)")
    name = system.name if system else model.stem
    proj = Projection(tuple(x.strip() for x in inputs), tuple(x.strip() for x in observables))
    return system, name, model, cfg, proj, _screen_config(args, system, cfg, decl, where)


def _screen_config(args: argparse.Namespace, system: Any, cfg: Path, decl: dict[str, Any],
                   where: str) -> Path | None:
    """The screening cfg: --screen-config, else the system's `[mutate] screen_config`
    when the cfg is its CI cfg (a screening cfg goes with the cfg it screens for);
    None with --no-screen.  Its properties must be the CI cfg's (or some of them), so
    that a kill there names a property the score is about."""
    if args.no_screen:
        return None
    if args.screen_config:
        screen, origin = Path(args.screen_config), "--screen-config"
    elif system is not None and "screen_config" in decl and cfg.resolve() == system.ci_config.resolve():
        if not isinstance(decl["screen_config"], str):
            raise InputError(f"{where}: screen_config must be a cfg path (a string), "
                             f"got {type(decl['screen_config']).__name__}")
        screen, origin = system.root / decl["screen_config"], f"{where} screen_config"
    else:
        return None
    if not screen.is_file():
        raise InputError(f"{origin}: {screen}: no such cfg file")
    from ..checker.cfg import parse_config
    ci, sc = parse_config(str(cfg)), parse_config(str(screen))
    checked = {e.name for e in ci.invariants + ci.properties}
    extra = [e.name for e in sc.invariants + sc.properties if e.name not in checked]
    if extra:
        raise InputError(f"{screen}: the screening cfg checks {', '.join(extra)}, which {cfg} does not: a "
                         f"screening cfg checks the CI cfg's properties (or some of them) with other constants")
    if sc.check_deadlock and not ci.check_deadlock:
        raise InputError(f"{screen}: the screening cfg checks for deadlock, {cfg} does not")
    return screen


def _original(subject: Subject, name: str) -> tuple[str, ...]:
    """Checks the original; the invariants it violates itself (a defective reference)
    are left out of every mutant's cfg.  Raises InputError when it does not check."""
    import tempfile

    from ..checker.model import load_model
    from .classify import check_model
    dropped: tuple[str, ...] = ()
    model = subject.load_original()
    unknown = [v for v in subject.projection.inputs + subject.projection.observables if v not in model.variables]
    if unknown:
        raise InputError(f"{name}: [mutate] names {', '.join(unknown)}, not variables of {subject.model} "
                         f"(variables: {', '.join(model.variables)})")
    for _ in range(len(model.invariants) + 1):
        with tempfile.TemporaryDirectory(prefix="safestate-mutate-") as tmp:
            subject.dropped = dropped
            tla, cfg = materialise(subject, None, Path(tmp))
            r = check_model(load_model(str(tla), str(cfg)), subject.engine, subject.max_memory_mb)
        if r.result == "success":
            break
        if r.result == "safety failure" and r.violated:
            dropped = dropped + (r.violated,)
            continue
        raise InputError(f"{subject.model} with {subject.cfg}: the original does not check ({r.result}"
                         f"{' ' + r.violated if r.violated else ''}); fix it before measuring its mutants")
    else:
        raise InputError(f"{subject.model}: the original violates every invariant")
    if subject.screen is not None:
        with tempfile.TemporaryDirectory(prefix="safestate-mutate-") as tmp:
            tla, cfg = materialise(subject, None, Path(tmp), screen=True)
            r = check_model(load_model(str(tla), str(cfg)), subject.engine, subject.max_memory_mb)
        if r.result != "success":
            raise InputError(f"{subject.model} with the screening cfg {subject.screen}: the original does not "
                             f"check ({r.result}{' ' + r.violated if r.violated else ''}): a kill there would "
                             f"not be the mutant's")
    return dropped


def stratified(mutants: list[Mutant], n: int, seed: int) -> list[Mutant]:
    """n mutants, each operator's share proportional to its count (at least one each
    while n allows), chosen with `seed`; returned in source order."""
    if n >= len(mutants):
        return list(mutants)
    rng = random.Random(seed)
    groups: dict[str, list[Mutant]] = {}
    for m in mutants:
        groups.setdefault(m.operator, []).append(m)
    for g in groups.values():
        rng.shuffle(g)
    quota = {op: min(len(g), max(1, n * len(g) // len(mutants))) for op, g in groups.items()}
    while sum(quota.values()) > n:
        biggest = max(quota, key=lambda o: quota[o])
        quota[biggest] -= 1
    ops = sorted(groups, key=lambda o: len(groups[o]) * n / len(mutants) - quota[o], reverse=True)
    while sum(quota.values()) < n:
        for op in ops:
            if quota[op] < len(groups[op]) and sum(quota.values()) < n:
                quota[op] += 1
    chosen = {m.id for op, g in groups.items() for m in g[:quota[op]]}
    return [m for m in mutants if m.id in chosen]


def _run(args: argparse.Namespace) -> int:
    start = time.monotonic()
    if args.sample is not None and args.sample < 1:
        raise InputError("--sample must be at least 1")
    if args.workers < 1:
        raise InputError("--workers must be at least 1")
    if args.min_score is not None and not 0 <= args.min_score <= 1:
        raise InputError("--min-score is a fraction between 0 and 1")
    system, name, model, cfg, proj, screen = _resolve(args)
    justs = results.justifications(system) if system is not None else []
    from ..checker.cfg import parse_config
    conf = parse_config(str(cfg))
    mutants = generate(model, conf.init.name if conf.init else None, conf.next.name if conf.next else None,
                       conf.specification.name if conf.specification else None, args.operator, proj.inputs)
    generated = len(mutants)
    try:
        mutants, duplicates = dedupe(mutants, model.parent)
    except OSError as e:
        raise InputError(f"{model.parent}: {e}") from None
    if args.only:
        mutants = [m for m in mutants if any(t in m.id for t in args.only)]
        if not mutants:
            raise InputError(f"--only {' '.join(args.only)}: no generated mutant's id contains it (--list shows them)")
    chosen = stratified(mutants, args.sample, args.seed) if args.sample else mutants
    if args.list:
        for m in chosen:
            print(f"# {m.id}: {m.what}\n{m.toml(_folder(model))}")
        return 0
    subject = Subject(model, cfg, proj, screen=screen, engine=args.engine, timeout=args.timeout)
    cache = Cache(None, enabled=not args.no_cache)
    known = cache.get_original(subject)
    subject.dropped = known.dropped if known else _original(subject, name)
    outcomes: dict[str, Outcome] = {}
    todo: list[Mutant] = []
    for m in chosen:
        hit = cache.get(subject, m)
        if hit is not None:
            outcomes[m.id] = hit
        else:
            todo.append(m)
    if todo:
        print(f"mutate: {name}: exploring the original once (its graph) for the difference searches",
              file=sys.stderr, flush=True)
    if todo or known is None:
        prepare(subject, search=bool(todo))  # and which witnesses it reaches, for the report
        found = subject.witnesses or WitnessSet()
        cache.put_original(subject, OriginalRecord(subject.dropped, found.names, found.not_reached))
    else:  # every outcome cached: what the original reaches is cached too, nothing is checked
        subject.witnesses = WitnessSet(names=known.witnesses, not_reached=known.not_reached)
    progress = _Progress(len(chosen), len(outcomes), len(todo))

    def done(m: Mutant, o: Outcome) -> None:
        cache.put(subject, m, o)
        outcomes[m.id] = o
        progress.step(m, o)
    if todo:
        classify_all(subject, todo, args.workers, done)
    ordered = [outcomes[m.id] for m in chosen]
    s = summary(name, generated, chosen, ordered, time.monotonic() - start, subject.dropped,
                sampled=len(chosen) < len(mutants), duplicates=len(duplicates), screen=screen.name if screen else None)
    ws = subject.witnesses
    s.update(sample=args.sample, seed=args.seed if args.sample else None, selected_operators=args.operator,
             only=args.only, when=time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), cfg=str(cfg),
             witnesses=list(ws.names) if ws else [], witnesses_not_reached=list(ws.not_reached) if ws else [])
    results.justify(s, justs)
    if system is not None and not args.operator and not args.only and (
            args.config is None or Path(args.config).resolve() == system.ci_config.resolve()):
        results.write(system, s)  # the system's last score (all operators): safestate systems, evidence
    if args.itf_dir:
        _write_itf(Path(args.itf_dir), name, ordered)
    if args.json:
        print(json.dumps(s))
    else:
        write_text(sys.stdout, s, chosen, ordered)
    sc = score(ordered)
    if args.min_score is not None and (sc is None or sc < args.min_score):
        print(f"mutation score {'n/a' if sc is None else f'{sc:.3f}'} is below --min-score {args.min_score}",
              file=sys.stderr)
        return BELOW_MIN_SCORE
    return 0


def _folder(model: Path) -> str:
    """The model's folder as models/mutants/*.toml names it: relative to the repository
    (the registry's parent), else to the current directory."""
    from ..systems.registry import registry_dir
    folder = model.resolve().parent
    for base in (registry_dir().resolve().parent, Path.cwd().resolve()):
        if folder.is_relative_to(base):
            return str(folder.relative_to(base)) or "."
    return str(folder)


def _write_itf(folder: Path, name: str, outcomes: list[Outcome]) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for o in outcomes:
            if o.status == "survived" and o.itf:
                safe = "".join(c if c.isalnum() or c in "-_" else "_" for c in o.mutant)
                (folder / f"{name}_{safe}.itf.json").write_text(json.dumps(o.itf, indent=1) + "\n", encoding="utf-8")
    except OSError as e:
        raise InputError(f"--itf-dir {folder}: {e}") from None


class _Progress:
    """One stderr line per classified mutant, with the ETA from the mean time so far."""

    def __init__(self, total: int, cached: int, todo: int) -> None:
        self.total, self.done, self.todo, self.start = total, cached, todo, time.monotonic()
        self.fresh = 0
        if cached:
            print(f"mutate: {cached} of {total} outcomes from the cache, {todo} to classify", file=sys.stderr)

    def step(self, m: Mutant, o: Outcome) -> None:
        self.done += 1
        self.fresh += 1
        el = time.monotonic() - self.start
        eta = el / self.fresh * (self.todo - self.fresh)
        print(f"mutate: [{self.done}/{self.total}] {o.status:<10} {m.id} ({o.seconds:.1f} s, {o.cpu:.1f} CPU s) "
              f"ETA {int(eta // 60)}:{int(eta % 60):02d}", file=sys.stderr, flush=True)
