"""Errors raised by the TLA+ front end and evaluator, each with a source position.

Every user-facing failure is a `TlaError`: it carries a `kind` (``syntax``,
``semantic``, ``unsupported``, ``eval``, ``config``, ``assumption``), a one-line
message in TLC-like wording, and the position (file, line, column; 1-based) of the
construct that caused it.  The CLI prints ``file:line:column: message``.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Loc:
    """A 1-based source position."""

    file: str
    line: int
    column: int

    def __str__(self) -> str:
        # Line 0: the file as a whole (it is missing or unreadable), no position in it.
        if self.line <= 0:
            return self.file
        return f"{self.file}:{self.line}:{self.column}"


NO_LOC = Loc("<unknown>", 0, 0)


class TlaError(Exception):
    """A user-facing error in a TLA+ module, a .cfg file, or during evaluation."""

    def __init__(self, kind: str, message: str, loc: Loc | None = None) -> None:
        super().__init__(message)
        self.kind = kind
        self.message = message
        self.loc = loc

    def with_loc(self, loc: Loc) -> "TlaError":
        """Attach `loc` if the error has no position yet (innermost position wins)."""
        if self.loc is None:
            self.loc = loc
        return self

    def __str__(self) -> str:
        return f"{self.loc}: {self.message}" if self.loc else self.message


class EvalError(TlaError):
    """A run-time evaluation failure (type error, domain error, CHOOSE without witness...)."""

    def __init__(self, message: str, loc: Loc | None = None) -> None:
        super().__init__("eval", message, loc)


class ModuleEvalError(EvalError):
    """An error TLC raises inside a standard module's Java code (Head of <<>>, \\div 0,
    % 0): TLC exits with 255 for it while computing successors (75 in Init, 76 in an
    invariant, like any evaluation error)."""


class JavaOverrideError(EvalError):
    """An error TLC meets as a Java exception inside an operator it implements in Java,
    not as its own evaluation error: `..` applied to a non-integer (TLC: "Cannot cast
    ... to IntValue").  TLC exits with 75 for it while computing successors, but with
    255 when its liveness check meets the error again on the same state (see
    `checker/explore.py`)."""


class UnassignedPrimeError(EvalError):
    """x' read before the action has given it a value."""


class UnsupportedError(TlaError):
    """A construct outside the supported subset (see docs/tla-subset.md)."""

    def __init__(self, message: str, loc: Loc | None = None) -> None:
        super().__init__("unsupported", message, loc)


class AssertFailure(EvalError):
    """TLC!Assert with a false condition (TLC exits with its own code for it)."""

    def __init__(self, message: str, loc: Loc | None = None) -> None:
        super().__init__(message, loc)
        self.kind = "assert"
