# The native core of `safestate check --engine native` (bindings/python/tla_native/):
# a compiled pybind11 module without type information, so its members are Any to mypy.
from typing import Any

def __getattr__(name: str) -> Any: ...
