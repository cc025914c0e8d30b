"""`safestate conform`: evidence that a system's C++ does what its TLA+ model says.

Generic over the systems of the registry (`safestate.systems`): each system's adapter
(`adapter.Adapter`, systems/<Name>/adapter.py) maps model events to C++ calls and
model states to what the C++ observes.  Trace cover of the model's reachable state
graph (`cover`, `traces`, `graph` with its on-disk cache), replay of each trace step
through the binding (`replay`), Hypothesis lockstep testing (`lockstep`), the
input-complete pass (`input_complete`), the transition-table audit (`audit`) and the
CLI (`cli`).
"""
