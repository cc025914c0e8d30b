"""safestate: formally verified safety state machines (TLA+ models, a TLC-equivalent
model checker, z3 proofs, and a C++17 implementation checked against them)."""

__version__ = "0.1.0"
