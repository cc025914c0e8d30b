"""The TLC-equivalent explicit-state model checker (``safestate check``).

Stable API: ``safestate.checker.model.load_model`` and
``safestate.checker.explore.explore_states``.
"""
