"""The configuration file of `safestate saf` (saf.toml, design §14): addresses, ports and
component ids of the service, the Safety Client and the subsystem, the six SAF-04
parameters, and the freshness and authentication settings (the key file of both links,
the service's sequence file). One file serves all three
processes, so that their views of each other cannot disagree."""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import UsageError

PARAMETERS: dict[str, float] = {
    "CYCLEINTERVAL": 0.05,
    "ESTOPTIMEOUT": 0.1,
    "REPORTDATATIMEOUT": 2.0,
    "MESSAGEINTERVAL": 0.5,
    "CHECKINTERVAL": 1.0,
}
AUTHORITY_DEFAULT = 225


@dataclass(frozen=True)
class Endpoint:
    address: str
    port: int
    component_id: int


@dataclass(frozen=True)
class SafConfig:
    path: Path
    service: Endpoint  # port: where the Safety Client sends Set Estop
    service_subsystem_port: int  # the service's socket towards the subsystem
    client: Endpoint
    subsystem: Endpoint
    service_timeout_s: float  # subsystem simulator: EMERGENCY after this long without the service
    parameters: dict[str, float]  # the five times in seconds
    authority_code: int
    require_sequence: bool
    replay_window: int
    key_file: Path | None
    sequence_file: Path | None  # the service's replay state across a restart (design §15)

    def binding_parameters(self) -> dict[str, float | int]:
        return {**self.parameters, "AUTHORITYCODE": self.authority_code}


class _Reader:
    """Typed access to the parsed TOML with errors naming the file, the line and what was
    expected (tomllib keeps no positions: the line is found by the key's text)."""

    def __init__(self, path: Path, text: str, data: dict[str, Any]) -> None:
        self.path, self.lines, self.data = path, text.splitlines(), data

    def where(self, table: str, key: str | None = None) -> str:
        section = -1
        for i, line in enumerate(self.lines):
            if re.match(rf"^\s*\[\s*{re.escape(table)}\s*\]", line):
                section = i
                if key is None:
                    return f"{self.path}:{i + 1}"
                continue
            if section >= 0 and key is not None:
                if re.match(r"^\s*\[", line):
                    break
                if re.match(rf"^\s*{re.escape(key)}\s*=", line):
                    return f"{self.path}:{i + 1}"
        return f"{self.path}:{section + 1}" if section >= 0 else str(self.path)

    def fail(self, table: str, key: str | None, expected: str, got: object = None) -> UsageError:
        name = f"[{table}] {key}" if key else f"[{table}]"
        tail = f", got {got!r}" if got is not None else ""
        return UsageError(f"{self.where(table, key)}: {name}: expected {expected}{tail}")

    def table(self, name: str, required: bool = True) -> dict[str, Any]:
        t = self.data.get(name)
        if t is None:
            if required:
                raise UsageError(f"{self.path}: missing table [{name}]")
            return {}
        if not isinstance(t, dict):
            raise self.fail(name, None, "a table")
        return t

    def port(self, table: str, key: str, allow_zero: bool = False) -> int:
        t = self.table(table)
        if key not in t:
            raise UsageError(f"{self.where(table)}: [{table}] has no '{key}' (a UDP port)")
        v = t[key]
        low = 0 if allow_zero else 1
        if isinstance(v, bool) or not isinstance(v, int) or not low <= v <= 65535:
            raise self.fail(table, key, f"a UDP port {low}..65535", v)
        return v

    def address(self, table: str) -> str:
        v = self.table(table).get("address", "127.0.0.1")
        if not isinstance(v, str) or not re.fullmatch(r"(\d{1,3})\.(\d{1,3})\.(\d{1,3})\.(\d{1,3})", v) or any(
            int(p) > 255 for p in v.split(".")
        ):
            raise self.fail(table, "address", "an IPv4 address a.b.c.d", v)
        return v

    def component_id(self, table: str) -> int:
        t = self.table(table)
        if "component_id" not in t:
            raise UsageError(f"{self.where(table)}: [{table}] has no 'component_id' (a 32-bit id, e.g. 0x00010300)")
        v = t["component_id"]
        if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 0xFFFFFFFF:
            raise self.fail(table, "component_id", "a component id 1..0xFFFFFFFF", v)
        return v

    def seconds(self, table: str, key: str, default: float) -> float:
        v = self.table(table, required=False).get(key, default)
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v) or v <= 0:
            raise self.fail(table, key, "a positive number of seconds", v)
        return float(v)


def load(path: str | Path) -> SafConfig:
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as e:
        raise UsageError(f"{p}: cannot read the configuration ({e.strerror or e})") from None
    except UnicodeDecodeError:
        raise UsageError(f"{p}: the configuration is not UTF-8 text") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise UsageError(f"{p}: not valid TOML: {e}") from None
    r = _Reader(p, text, data)
    known = {"service", "client", "subsystem", "parameters", "security"}
    for name in data:
        if name not in known:
            raise UsageError(f"{r.where(name)}: unknown table [{name}] (expected one of {', '.join(sorted(known))})")
    parameters = {k: r.seconds("parameters", k, d) for k, d in PARAMETERS.items()}
    extra = set(r.table("parameters", required=False)) - {*PARAMETERS, "AUTHORITYCODE"}
    if extra:
        key = sorted(extra)[0]
        raise r.fail("parameters", key, f"one of {', '.join([*PARAMETERS, 'AUTHORITYCODE'])}", key)
    authority = r.table("parameters", required=False).get("AUTHORITYCODE", AUTHORITY_DEFAULT)
    if isinstance(authority, bool) or not isinstance(authority, int) or not 0 <= authority <= 255:
        raise r.fail("parameters", "AUTHORITYCODE", "an authority code 0..255", authority)
    security = r.table("security", required=False)
    require_sequence = security.get("require_sequence", True)
    if not isinstance(require_sequence, bool):
        raise r.fail("security", "require_sequence", "true or false", require_sequence)
    window = security.get("replay_window", 64)
    if isinstance(window, bool) or not isinstance(window, int) or not 1 <= window <= 1 << 32:
        raise r.fail("security", "replay_window", "a whole number 1..2^32", window)
    key_file = security.get("key_file")
    if key_file is not None and (not isinstance(key_file, str) or not key_file):
        raise r.fail("security", "key_file", "a path (relative to the configuration file)", key_file)
    sequence_file = security.get("sequence_file")
    if sequence_file is not None and (not isinstance(sequence_file, str) or not sequence_file):
        raise r.fail("security", "sequence_file", "a path (relative to the configuration file)", sequence_file)
    if key_file is not None and not require_sequence:
        raise r.fail("security", "require_sequence", "true when key_file is given (the MAC covers the sequence)")
    service_timeout_default = 2 * parameters["MESSAGEINTERVAL"]
    return SafConfig(
        path=p,
        service=Endpoint(r.address("service"), r.port("service", "client_port"), r.component_id("service")),
        service_subsystem_port=r.port("service", "subsystem_port"),
        client=Endpoint(r.address("client"), r.port("client", "port"), r.component_id("client")),
        subsystem=Endpoint(r.address("subsystem"), r.port("subsystem", "port"), 0),
        service_timeout_s=r.seconds("subsystem", "service_timeout", service_timeout_default),
        parameters=parameters,
        authority_code=authority,
        require_sequence=require_sequence,
        replay_window=window,
        key_file=(p.parent / key_file) if key_file else None,
        sequence_file=(p.parent / sequence_file) if sequence_file else None,
    )


def load_key(cfg: SafConfig) -> bytes | None:
    """The HMAC key of [security] key_file, read by the C++ (mode 0600/0400 only), or None."""
    if cfg.key_file is None:
        return None
    from .._saf_net import load_key_file  # type: ignore[import-not-found]

    try:
        return bytes(load_key_file(str(cfg.key_file)))
    except ValueError as e:
        raise UsageError(str(e)) from None
