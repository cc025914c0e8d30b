"""`safestate conform`: evidence that the C++ SystemStateManager does what the TLA+
model says (docs/design/system-state-manager.md).

Trace cover of the model's reachable state graph (`cover`, `traces`), replay of each
trace step through the pybind11 binding (`replay`), Hypothesis lockstep testing
(`lockstep`), the transition-table audit (`audit`) and the CLI (`cli`).
"""
