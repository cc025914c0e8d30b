"""Reading the system manifests (`systems/<Name>/system.toml`).

The registry folder is $SAFESTATE_SYSTEMS, else the first `systems/` folder holding a
manifest found from the current directory upwards, else the repository's own (beside
`python/`).  Paths in a manifest are relative to the repository root (the registry
folder's parent); the adapter path is relative to the manifest's folder.
"""

from __future__ import annotations

import importlib.util
import os
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


def load_all(directory: Path | None = None) -> list[System]:
    d = directory or registry_dir()
    return [load_manifest(p) for p in sorted(d.glob(f"*/{MANIFEST}"))]


def find(name: str, directory: Path | None = None) -> System | None:
    for s in load_all(directory):
        if s.name == name:
            return s
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
    try:
        with open(path, "rb") as f:
            doc = tomllib.load(f)
    except tomllib.TOMLDecodeError as e:
        raise RegistryError(f"{path}: {e}") from None
    root = path.parent.parent.parent
    rel = lambda p: root / p  # noqa: E731
    conf = None
    if "conformance" in doc:
        c = doc["conformance"]
        where = Path(f"{path} [conformance]")
        conf = Conformance(binding=_req(c, "binding", str, where),
                           adapter=path.parent / _req(c, "adapter", str, where),
                           adapter_class=_req(c, "class", str, where),
                           config=rel(c["config"]) if "config" in c else None,
                           hypothesis_steps=int(c.get("hypothesis_steps", 0)),
                           test_hypothesis_steps=int(c.get("test_hypothesis_steps", 0)))
    configs = [rel(p) for p in _req(doc, "configs", list, path)]
    return System(
        name=_req(doc, "name", str, path),
        summary=doc.get("summary", ""),
        manifest=path,
        root=root,
        design=rel(_req(doc, "design", str, path)),
        model=rel(_req(doc, "model", str, path)),
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
        names = ", ".join(s.name for s in load_all(directory)) or "none"
        raise RegistryError(f"{arg}: not a registered system (registered: {names}) and not a .tla file")
    cfg = config or str(system.conformance.config if system.conformance and system.conformance.config
                        else system.ci_config)
    return system, str(system.model), cfg
