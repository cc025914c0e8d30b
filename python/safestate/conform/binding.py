"""Which compiled binding to drive: `safestate._core` by default; the wrong variant
and the coverage build are the same API under another module name."""

from __future__ import annotations

import importlib
import os
import sys
from types import ModuleType

from ..errors import UsageError

DEFAULT = "safestate._core"
ENV = "SAFESTATE_CORE_MODULE"      # e.g. safestate_cov._core
PATH_ENV = "SAFESTATE_CORE_PATH"   # a directory to put on sys.path first


def load_core(name: str | None = None, path: str | None = None) -> ModuleType:
    path = path or os.environ.get(PATH_ENV)
    if path and path not in sys.path:
        sys.path.insert(0, path)
    module = name or os.environ.get(ENV) or DEFAULT
    try:
        return importlib.import_module(module)
    except ImportError as e:
        raise UsageError(f"binding module {module} cannot be imported ({e})") from None
