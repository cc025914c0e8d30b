"""`safestate saf serve`: the Safety service as a process. The C++ ServiceHost (sockets,
intake, core) runs one scan cycle per CYCLEINTERVAL; this loop logs every state change
and every rejected datagram (one line each) and stops cleanly on SIGTERM or SIGINT,
printing its counters. A stopped service holds the subsystem in nothing: the subsystem
notices the silence (design §14) and goes to EMERGENCY. With `[security] sequence_file`
the replay state (the highest accepted Set Estop and subsystem sequences, our own next
link sequence) is read at start and stored after every cycle in which it moved, between
cycles (design §15): a datagram captured before a restart is stale after it."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

from ..errors import UsageError
from .config import SafConfig, load, load_key
from .events import EventLog
from .ticker import Ticker


Sequences = dict[str, int | None]


def load_sequences(path: Path) -> Sequences | None:
    """The sequence file's state, None when it does not exist (the first start); a file
    that exists but is not exactly a sequence file stops the service (exit 2): never a
    silent reset of the replay window."""
    from .._saf_net import load_sequence_file  # type: ignore[import-not-found]

    try:
        state: Sequences | None = load_sequence_file(str(path))
    except ValueError as e:
        raise UsageError(f"{e} (delete the file to start with an empty replay window)") from None
    return state


def store_sequences(path: Path, state: Sequences) -> None:
    from .._saf_net import store_sequence_file  # type: ignore[import-not-found]

    store_sequence_file(str(path), state["estop"], state["subsystem"], state["service"])


def make_host(cfg: SafConfig) -> Any:
    from .._saf_net import ServiceHost, validate_parameters  # type: ignore[import-not-found]

    verdict = validate_parameters(cfg.binding_parameters())
    if verdict != "NONE":
        raise UsageError(f"{cfg.path}: [parameters]: {verdict} (each time > 0 and at most 65,535 cycles)")
    host = ServiceHost(
        address=cfg.service.address,
        client_port=cfg.service.port,
        subsystem_port=cfg.service_subsystem_port,
        component_id=cfg.service.component_id,
        client_address=cfg.client.address,
        client_peer_port=cfg.client.port,
        client_component_id=cfg.client.component_id,
        subsystem_address=cfg.subsystem.address,
        subsystem_peer_port=cfg.subsystem.port,
        parameters=cfg.binding_parameters(),
        require_sequence=cfg.require_sequence,
        replay_window=cfg.replay_window,
        key=load_key(cfg),
        # Our sealed messages to the subsystem start above anything sent before a restart
        # (the stored next sequence, restored below, can only raise it).
        link_sequence_start=time.time_ns() // 1000,
    )
    try:
        host.open()
    except ValueError as e:
        raise UsageError(
            f"{cfg.path}: [service] {cfg.service.address} ports {cfg.service.port}/{cfg.service_subsystem_port}: {e}"
        ) from None
    return host


def run(args: argparse.Namespace) -> int:
    cfg = load(args.config)
    stored = load_sequences(cfg.sequence_file) if cfg.sequence_file else None
    host = make_host(cfg)
    log = EventLog("service", args.json)
    if cfg.sequence_file is not None:
        if stored is not None:
            host.restore(stored["estop"], stored["subsystem"], stored["service"])
            log.emit("sequences", f"restored from {cfg.sequence_file}: Set Estop above {stored['estop']}, "
                     f"subsystem above {stored['subsystem']}", file=str(cfg.sequence_file), restored=True,
                     **stored)
        else:
            log.emit("sequences", f"{cfg.sequence_file} does not exist: first start, created",
                     file=str(cfg.sequence_file), restored=False)
        stored = host.sequences()
        try:
            store_sequences(cfg.sequence_file, stored)
        except ValueError as e:
            raise UsageError(str(e)) from None
    store_failing = False
    # SIGTERM/SIGINT handlers before "started": a supervisor that stops the service as
    # soon as it reports itself started must get the clean stop and its counters.
    ticker = Ticker(cfg.parameters["CYCLEINTERVAL"])
    auth = "HMAC-SHA256" if cfg.key_file else ("sequence" if cfg.require_sequence else "none")
    log.emit(
        "started",
        f"client port {host.client_port}, subsystem socket {host.subsystem_port} -> "
        f"{cfg.subsystem.address}:{cfg.subsystem.port}, Set Estop accepted from "
        f"{cfg.client.address}:{cfg.client.port} id {cfg.client.component_id:#010x}, freshness {auth}",
        client_port=host.client_port, subsystem_port=host.subsystem_port, state=host.state, freshness=auth,
    )
    cycles = args.cycles
    while ticker.running and (cycles is None or ticker.cycle < cycles):
        c = host.step()
        if c["before"] != c["after"]:
            log.emit("state", f"{c['before']} -> {c['after']} (row {c['state_row']})",
                     before=c["before"], after=c["after"], row=c["state_row"], sent=c["sent"])
        for r in c["rejected"]:
            what = f" {r['message']}" if r["message"] else ""
            log.emit("rejected", f"{r['reason']}{what} from {r['source']} on the {r['socket']} socket", **r)
        if c["kernel_dropped"]:
            log.emit("dropped", f"the kernel dropped {c['kernel_dropped']} datagrams (receive buffer full)",
                     count=c["kernel_dropped"])
        if cfg.sequence_file is not None:
            now = host.sequences()
            if now != stored:
                # Between cycles: the fsync is never inside the scan cycle. A failing store
                # is logged once and retried every cycle; the service keeps running (its
                # window across the next restart is then the last stored one).
                try:
                    store_sequences(cfg.sequence_file, now)
                    stored = now
                    if store_failing:
                        store_failing = False
                        log.emit("sequences", f"stored again in {cfg.sequence_file}", file=str(cfg.sequence_file))
                except ValueError as e:
                    if not store_failing:
                        store_failing = True
                        log.emit("sequence-store-failed", str(e), file=str(cfg.sequence_file))
        ticker.wait()
    counters = host.counters()
    rejected = {k: v for k, v in counters["rejected"].items() if v}
    log.emit("stopped", f"state {host.state}, {counters['cycles']} cycles ({ticker.late} late), "
             f"accepted {counters['accepted']}, rejected {rejected or 'none'}, "
             f"kernel drops {counters['kernel_dropped']}",
             state=host.state, late_cycles=ticker.late, **counters)
    return 0
