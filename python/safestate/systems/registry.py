"""Reading the system manifests (`systems/<Name>/system.toml`).

The registry folder is $SAFESTATE_SYSTEMS, else the first `systems/` folder holding a
manifest found from the current directory upwards, else the repository's own (beside
`python/`).  Paths in a manifest are relative to the repository root (the registry
folder's parent); the adapter path is relative to the manifest's folder.
"""

from __future__ import annotations

import importlib.util
import os
import re
import sys
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import Any

from ..errors import SafestateError

ENV = "SAFESTATE_SYSTEMS"
MANIFEST = "system.toml"


class RegistryError(SafestateError):
    """A manifest is missing, malformed or names something that is not there."""

    folder: str | None = None  # systems/<folder>/ of the manifest, when it is one


def _line_of(text: str, key: str) -> int | None:
    """The line (1-based) where `key = ...` is written, if it is."""
    for i, line in enumerate(text.splitlines(), 1):
        if re.match(rf"\s*{re.escape(key)}\s*=", line):
            return i
    return None


@dataclass
class Conformance:
    binding: str                  # Python module of the C++ binding, e.g. safestate._core
    adapter: Path                 # adapter module file
    adapter_class: str            # class in it
    config: Path | None = None    # the cfg conformance runs against (default: the system's ci_config)
    hypothesis_steps: int = 0     # Hypothesis lockstep steps of the main job
    test_hypothesis_steps: int = 0  # fewer (seeded) steps in the test suite; 0: the suite's default

    @property
    def wrong_binding(self) -> str:
        """The binding module of the deliberately wrong build (conform/wrong_variant/):
        the same module name in the package `safestate_wrong`."""
        return "safestate_wrong." + self.binding.rsplit(".", 1)[-1]


@dataclass
class System:
    name: str
    summary: str
    manifest: Path
    root: Path
    design: Path
    model: Path
    configs: list[Path]
    ci_config: Path
    proofs: Path | None
    mutants: Path | None
    requirements: list[str]
    conformance: Conformance | None
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def expected_violation(self) -> str | None:
        """The invariant a defective reference's model must violate (manifest key
        `expected_check = "violated INV"`), or None for a system whose checks must pass."""
        expected = str(self.extra.get("expected_check", ""))
        return expected.removeprefix("violated ").strip() or None

    def load_adapter_class(self) -> type:
        """The conformance adapter class (loaded from its file, by path)."""
        if self.conformance is None:
            raise RegistryError(f"{self.manifest}: system {self.name} has no [conformance] section")
        path = self.conformance.adapter
        if not path.is_file():
            raise RegistryError(f"{self.manifest}: adapter file {path} does not exist")
        module = _load_module(f"safestate_adapter_{self.name}", path)
        cls = getattr(module, self.conformance.adapter_class, None)
        if not isinstance(cls, type):
            raise RegistryError(f"{path}: no class {self.conformance.adapter_class}")
        return cls


def _load_module(name: str, path: Path) -> ModuleType:
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    # Registered before it runs, as an import would: @dataclass and typing look the
    # defining module up in sys.modules.
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def registry_dir(start: Path | None = None) -> Path:
    env = os.environ.get(ENV)
    if env:
        return Path(env)
    here = (start or Path.cwd()).resolve()
    for d in (here, *here.parents):
        cand = d / "systems"
        if any(cand.glob(f"*/{MANIFEST}")):
            return cand
    return Path(__file__).resolve().parents[3] / "systems"


def scan(directory: Path | None = None) -> tuple[list[System], list[RegistryError]]:
    """Every system whose manifest reads, and the error of each one that does not: a
    malformed manifest breaks its own system only."""
    d = directory or registry_dir()
    systems: list[System] = []
    broken: list[RegistryError] = []
    for p in sorted(d.glob(f"*/{MANIFEST}")):
        try:
            systems.append(load_manifest(p))
        except RegistryError as e:
            e.folder = p.parent.name
            broken.append(e)
    return systems, broken


def load_all(directory: Path | None = None) -> list[System]:
    """The systems whose manifest reads (`scan` also gives the broken ones)."""
    return scan(directory)[0]


def find(name: str, directory: Path | None = None) -> System | None:
    """The system `name`; its manifest's error when the manifest in systems/<name>/
    does not read."""
    systems, broken = scan(directory)
    for s in systems:
        if s.name == name:
            return s
    for e in broken:
        if e.folder == name:
            raise e
    return None


def for_model(model_path: str, directory: Path | None = None) -> System | None:
    """The system whose model is this .tla file, if any."""
    target = Path(model_path).resolve()
    for s in load_all(directory):
        if s.model.resolve() == target:
            return s
    return None


def _req(doc: dict[str, Any], key: str, typ: type, where: Path) -> Any:
    if key not in doc:
        raise RegistryError(f"{where}: missing key '{key}'")
    v = doc[key]
    if not isinstance(v, typ):
        raise RegistryError(f"{where}: '{key}' must be a {typ.__name__}, got {type(v).__name__}")
    return v


def load_manifest(path: Path) -> System:
    """The manifest at `path`; a RegistryError naming the file (and line, when known)."""
    try:
        data = path.read_bytes()
        text = data.decode("utf-8")
        doc = tomllib.loads(text)
    except OSError as e:
        raise RegistryError(f"{path}: cannot read the manifest ({e.strerror or e})") from None
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise RegistryError(f"{path}:{line}: the manifest is not UTF-8 text (TOML must be)") from None
    except tomllib.TOMLDecodeError as e:
        m = re.search(r"\(at line (\d+), column (\d+)\)", str(e))
        if m:
            where = f"{path}:{m.group(1)}:{m.group(2)}"
        else:  # "(at end of document)": the line after the last
            where = f"{path}:{text.count(chr(10)) + 1}:1" if "end of document" in str(e) else str(path)
        msg = re.sub(r"\s*\(at (line \d+, column \d+|end of document)\)", "", str(e))
        raise RegistryError(f"{where}: malformed TOML: {msg}") from None
    try:
        return _system(path, doc)
    except (TypeError, ValueError, IndexError, AttributeError) as e:
        raise RegistryError(f"{path}: malformed manifest ({e})") from None
    except RegistryError as e:
        key = re.search(r"'(\w+)' must be", str(e))
        at = _line_of(text, key.group(1)) if key else None
        if at is None:
            raise
        raise RegistryError(str(e).replace(f"{path}:", f"{path}:{at}:", 1)) from None


def _system(path: Path, doc: dict[str, Any]) -> System:
    root = path.parent.parent.parent
    rel = lambda p: root / p  # noqa: E731
    conf = None
    if "conformance" in doc:
        c = doc["conformance"]
        if not isinstance(c, dict):
            raise RegistryError(f"{path}: 'conformance' must be a table ([conformance]), got {type(c).__name__}")
        where = Path(f"{path} [conformance]")
        conf = Conformance(binding=_req(c, "binding", str, where),
                           adapter=path.parent / _req(c, "adapter", str, where),
                           adapter_class=_req(c, "class", str, where),
                           config=rel(c["config"]) if "config" in c else None,
                           hypothesis_steps=int(c.get("hypothesis_steps", 0)),
                           test_hypothesis_steps=int(c.get("test_hypothesis_steps", 0)))
    name, design, model = (_req(doc, k, str, path) for k in ("name", "design", "model"))
    configs = [rel(p) for p in _req(doc, "configs", list, path)]
    if not configs and "ci_config" not in doc:
        raise RegistryError(f"{path}: 'configs' is empty: a system needs at least one .cfg")
    return System(
        name=name,
        summary=doc.get("summary", ""),
        manifest=path,
        root=root,
        design=rel(design),
        model=rel(model),
        configs=configs,
        ci_config=rel(doc["ci_config"]) if "ci_config" in doc else configs[0],
        proofs=rel(doc["proofs"]) if "proofs" in doc else None,
        mutants=rel(doc["mutants"]) if "mutants" in doc else None,
        requirements=list(doc.get("requirements", [])),
        conformance=conf,
        extra={k: v for k, v in doc.items() if k not in {
            "name", "summary", "design", "model", "configs", "ci_config", "proofs", "mutants",
            "requirements", "conformance"}},
    )


def resolve_system(arg: str, config: str | None = None, directory: Path | None = None) -> tuple[System, str, str | None]:
    """(system, model path, cfg path) for a system name or a registered model path."""
    if arg.endswith(".tla") or os.sep in arg:
        if not os.path.isfile(arg):
            raise RegistryError(f"{arg}: no such model file")
        system = for_model(arg, directory)
        if system is None:
            raise RegistryError(f"{arg}: no system in the registry ({registry_dir()}) has this model; "
                                f"add systems/<Name>/system.toml (docs/adding-a-system.md)")
        return system, arg, config
    system = find(arg, directory)
    if system is None:
        systems, broken = scan(directory)
        names = ", ".join(s.name for s in systems) or "none"
        unread = f"; unreadable manifests: {', '.join(str(e.folder) for e in broken)}" if broken else ""
        raise RegistryError(f"{arg}: not a registered system (registered: {names}{unread}) and not a .tla file")
    cfg = config or str(system.conformance.config if system.conformance and system.conformance.config
                        else system.ci_config)
    return system, str(system.model), cfg
