"""The difference search on the native core's state graphs.

Where the native core accepts the model, the mutant's check (`classify.py`) records its
reachable graph as it searches, labelled for this search: per step, the source, the
stored target and the values of the inputs and observables *in the successor the step
produced* (under a VIEW the stored target may differ from it outside the VIEW, e.g. the
flagship's last_reject_reason).  The original's graph is recorded once, before the
workers fork.  The pair search is then `product.py`'s -- breadth-first over pairs
(original state, mutant state), at each pair and for each input value the sets of
observations compared, a difference ending it with the shortest input trace -- but
over integer state indices and precomputed labels instead of two evaluations of Next
per pair.  A check that stops at a violation (killed) never needs the graph.

Pairs are identified by the stored states (under a VIEW, by its fingerprints, as the
checker identifies states), and a pair's successors are those of its stored states, as
the checker explores them.  Under a VIEW that leaves out an observed variable kept from
step to step (the flagship's last_reject_reason), a stored state may carry another
value of it than the state it stands for, and a difference found here may be one of
the stored states only: `confirm` replays the difference trace on the exact states
(the Python engine) before it is reported; one not confirmed goes to `product.py`.

**Carried values under a VIEW.**  An action that leaves a labelled variable unchanged
(the flagship's Submit keeps `inputs`, whose free signals the VIEW leaves out) labels
its steps with the stored representative's value, which the original's and the
mutant's representatives of one pair need not share: the two sides' Submit steps would
never carry equal labels, a difference of stored states only at every Submit -- not
confirmed, so every such mutant went to the exact Python search (the flagship's
`unchanged obs_fieldbus_lost` mutant timed out there).  So under a VIEW the check also
records each step's action (leaf), and a label position that an action copies from
its source in *every* step of the model's graph is labelled "unchanged" in that
action's steps.  At pairs of exact states reached by one input trace (the pairs the
search stands for) both sides hold equal values of every labelled variable, so "
unchanged" stands for the same value on both sides and the comparison is the exact
one; at pairs of representatives it no longer sees their hidden values.  Where one
side's action copies and the other's does not, a difference may again be one of stored
states only: `confirm` still decides.
"""

from __future__ import annotations

import time
from array import array
from dataclasses import dataclass, field
from typing import Any

from ..checker.explore import CheckResult
from ..checker.model import Model
from .product import DiffStep, ProductResult, Projection

NO_SOURCE = 0xFFFFFFFF
Label = tuple[tuple, tuple]          # (input values, observable values), Python values
UNCHANGED = -1                       # a label position its action copies (see "Carried values")


@dataclass
class LabelledGraph:
    """One model's reachable graph: `initial` and per state its out-steps, each
    (label id, target); label ids decode (per engine) to (inputs, observables)."""

    bridge: Any
    n_inputs: int
    initial: list[tuple[int, int]] = field(default_factory=list)
    offsets: array = field(default_factory=lambda: array("q"))   # out-steps of state i: steps[offsets[i]:offsets[i+1]]
    val: array = field(default_factory=lambda: array("I"))
    dst: array = field(default_factory=lambda: array("I"))
    _labels: dict[int, Label] = field(default_factory=dict)
    canon: dict[tuple, int] = field(default_factory=dict)   # structural key -> int, shared by both graphs
    _cval: dict[int, int] = field(default_factory=dict)
    _clab: dict[Any, tuple[int, int]] = field(default_factory=dict)   # by label id, or (id, mask)
    _sig: dict[int, tuple[dict[int, list[int]], dict[int, int], bool]] = field(default_factory=dict)
    run: Any = None     # the NativeRun whose engine holds the stored states (witness.py)
    # Under a VIEW: per step (after the initial ones) its mask number, and per mask number
    # the label positions copied (`_copy_masks`); empty: no masks.
    step_mask: array = field(default_factory=lambda: array("I"))
    masks: list[frozenset[int]] = field(default_factory=lambda: [frozenset()])
    leaves: array | None = None     # under a VIEW: per step (after the initial ones) its action
    same: bool = False              # a mutant's graph equal to the original's (`same_graph`)

    def share(self, other: "LabelledGraph") -> None:
        """Canonical label numbers comparable with `other`'s (one table for both)."""
        self.canon = other.canon

    def _value(self, vid: int) -> int:
        """The value's structural number: equal values of two engines get one number."""
        c = self._cval.get(vid)
        if c is None:
            kind, payload = self.bridge.engine.describe(vid)
            key = (kind, tuple(map(self._value, payload))) if isinstance(payload, list) else (kind, payload)
            c = self._cval[vid] = self.canon.setdefault(key, len(self.canon))
        return c

    def canonical(self, vid: int, mask: int = 0) -> tuple[int, int]:
        """(the label's number, its inputs' number), the positions of `masks[mask]`
        labelled UNCHANGED."""
        key = vid if mask == 0 else (vid, mask)
        lab = self._clab.get(key)
        if lab is None:
            _kind, payload = self.bridge.engine.describe(vid)
            parts = tuple(map(self._value, payload))
            if mask:
                copied = self.masks[mask]
                parts = tuple(UNCHANGED if i in copied else x for i, x in enumerate(parts))
            ik = self.canon.setdefault(("in",) + parts[:self.n_inputs], len(self.canon))
            lab = self._clab[key] = (self.canon.setdefault(("label",) + parts, len(self.canon)), ik)
        return lab

    def mask_of(self, j: int) -> int:
        """The mask number of step j (an index into `val`; 0 for an initial step)."""
        k = j - len(self.initial)
        return self.step_mask[k] if 0 <= k < len(self.step_mask) else 0

    def masked(self, vid: int, mask: int) -> Label:
        """The label's Python values with the copied positions as None."""
        i, o = self.label(vid)
        if not mask:
            return i, o
        copied, n = self.masks[mask], len(i)
        return (tuple(None if p in copied else x for p, x in enumerate(i)),
                tuple(None if p + n in copied else x for p, x in enumerate(o)))

    def signature(self, i: int) -> tuple[dict[int, list[int]], dict[int, int], bool]:
        """State i's steps: {label number: targets}, {label number: a label id of it}, and
        whether it chooses more than its inputs (two steps with one input)."""
        sig = self._sig.get(i)
        if sig is None:
            by: dict[int, list[int]] = {}
            vid_of: dict[int, int] = {}
            inputs: set[int] = set()
            a, b = (self.offsets[i], self.offsets[i + 1]) if i >= 0 else (0, 0)
            pairs = zip(self.val[a:b], self.dst[a:b], map(self.mask_of, range(a, b))) if i >= 0 else (
                (v, d, 0) for v, d in self.initial)
            for vid, d, mk in pairs:
                lab, ik = self.canonical(vid, mk)
                inputs.add(ik)
                ds = by.setdefault(lab, [])
                vid_of.setdefault(lab, vid)
                if d not in ds:
                    ds.append(d)
            nondet = len(inputs) < len(by) or any(len(ds) > 1 for ds in by.values())
            sig = self._sig[i] = (by, vid_of, nondet)
        return sig

    def label(self, vid: int) -> Label:
        lab = self._labels.get(vid)
        if lab is None:
            t = self.bridge.to_python(vid)
            lab = self._labels[vid] = (tuple(t[:self.n_inputs]), tuple(t[self.n_inputs:]))
        return lab

    def steps(self, i: int) -> list[tuple[int, int, int]]:
        """State i's steps (-1: the initial ones): (label id, target, mask number)."""
        if i < 0:
            return [(v, d, 0) for v, d in self.initial]
        a, b = self.offsets[i], self.offsets[i + 1]
        return list(zip(self.val[a:b], self.dst[a:b], map(self.mask_of, range(a, b))))


def native_labelled(model: Model, proj: Projection, max_memory_mb: int | None,
                    original: LabelledGraph | None = None
                    ) -> tuple[CheckResult | None, LabelledGraph | None, str]:
    """The native check of `model` recording its labelled graph: (result, graph, "");
    graph None when the check did not succeed; (None, None, why) after an evaluation
    error (the caller checks again with the Python engine for TLC's report).  Raises
    UnsupportedError when the core does not accept the model.  With the `original`'s
    graph, a graph equal to it is marked `same` (and its copy masks are the original's)."""
    from ..checker.native.search import NativeRun, explore_native
    run = NativeRun(model)
    eng = run.engine
    index = {v: i for i, v in enumerate(model.variables)}
    eng.label_vars = [index[v] for v in proj.inputs + proj.observables]
    viewed = model.config.view is not None
    if viewed:
        eng.record_edges = True  # each step's action, for the copy masks (module docstring)
    result, error = explore_native(model, max_memory_mb, None, run, 1)
    if result is None:
        return None, None, error
    if result.result != "success":
        return result, None, ""
    src, dst, val = (array("I", b) for b in eng.labels_bytes())
    g = LabelledGraph(run.bridge, len(proj.inputs), run=run)
    n = result.distinct_states
    k = 0
    while k < len(src) and src[k] == NO_SOURCE:
        g.initial.append((val[k], dst[k]))
        k += 1
    # The core expands states in index order, so each state's steps are contiguous.
    offsets = array("q", [0]) * (n + 1)
    counts = array("q", [0]) * (n + 1)
    for s in src[k:]:
        counts[s + 1] += 1
    acc = k
    for i in range(n + 1):
        acc += counts[i]
        offsets[i] = acc
    g.offsets, g.val, g.dst = offsets, val, dst
    leaves = array("I", eng.edges_bytes()[2]) if viewed else None
    if leaves is not None and len(leaves) != len(val) - k:
        leaves = None
    if original is not None and same_graph(original, g, leaves):
        g.same, g.step_mask, g.masks = True, original.step_mask, original.masks
    elif leaves is not None:
        g.step_mask, g.masks = _copy_masks(eng, leaves, len(eng.label_vars))
    if original is None:
        g.leaves = leaves
    return result, g, ""


def same_graph(orig: LabelledGraph, g: LabelledGraph, leaves: array | None) -> bool:
    """Whether `g` is `orig`'s graph: the same states in the same order (the core's
    search order is deterministic), the same steps with structurally equal labels, and
    under a VIEW the same action per step.  The copy masks are then the original's too
    (a stored state's labelled values are those of the step that first reached it), and
    the two are observationally equivalent: every pair the difference search would
    reach is a state with itself.  This decides the mutants that change nothing
    observable and nothing the search order sees without the pair search (the
    flagship's equivalents: the pair search is the largest Python part of their
    classification)."""
    if len(orig.initial) != len(g.initial) or orig.offsets != g.offsets or orig.dst != g.dst:
        return False
    if (orig.leaves is None) != (leaves is None) or (leaves is not None and orig.leaves != leaves):
        return False
    g.share(orig)
    lo = {v: orig.canonical(v)[0] for v in set(orig.val)}
    lm = {v: g.canonical(v)[0] for v in set(g.val)}
    return list(map(lo.__getitem__, orig.val)) == list(map(lm.__getitem__, g.val))


def _copy_masks(eng: Any, leaves: array, n_labels: int) -> tuple[array, list[frozenset[int]]]:
    """Per step after the first k (the initial ones), the number of its action's mask:
    the label positions that action copies from its (stored) source in every step.  The
    core computes the positions per action (`copy_masks`, over its recorded labels and
    edges); this numbers the distinct masks.  Past 64 labelled variables the core gives
    none: no position is then taken as copied, and a difference of stored states only is
    not confirmed, so the exact search (`product.py`) decides: slower, the same verdict."""
    bits = eng.copy_masks()
    if not bits:
        return array("I"), [frozenset()]
    copied = [frozenset(q for q in range(n_labels) if b >> q & 1) for b in bits]
    masks: list[frozenset[int]] = [frozenset()]
    number: dict[frozenset[int], int] = {frozenset(): 0}
    for c in copied:
        if c not in number:
            number[c] = len(masks)
            masks.append(c)
    of_leaf = [number[c] for c in copied]
    return array("I", (of_leaf[lf] for lf in leaves)), masks


def graph_search(orig: LabelledGraph, mut: LabelledGraph, proj: Projection, max_pairs: int = 2_000_000,
                 deadline: float | None = None) -> ProductResult:
    """`product.search` over two labelled graphs (see the module docstring).  The sets of
    observations per input agree at a pair exactly when the sets of its steps' labels
    (input, observation) agree, so a pair is compared by the labels' structural numbers;
    only a difference is grouped by input, in Python values, for its trace.  `deadline`:
    a value of `time.process_time()` (the budget is CPU seconds)."""
    mut.share(orig)
    nondet = False
    parents: list[int] = []
    pairs: list[tuple[int, int]] = []
    via: list[tuple[int, int]] = []   # per pair: the label ids (original, mutant) of its step
    seen: set[tuple[int, int]] = set()

    def trace_to(k: int, last: DiffStep) -> list[DiffStep]:
        out: list[DiffStep] = [last]
        while k >= 0:
            a, b = via[k]
            i, oa = orig.label(a)
            _, ob = mut.label(b)
            out.append(DiffStep(dict(zip(proj.inputs, i)), dict(zip(proj.observables, oa)),
                                dict(zip(proj.observables, ob))))
            k = parents[k]
        out.reverse()
        return out

    def differing(o: int, m: int, parent: int) -> list[DiffStep]:
        go = _grouped(orig, o)
        gm = _grouped(mut, m)
        for v in list(go) + [v for v in gm if v not in go]:
            a, b = go.get(v, {}), gm.get(v, {})
            if a.keys() != b.keys():
                only_a = [a[x] for x in a if x not in b] or list(a.values())
                only_b = [b[x] for x in b if x not in a] or list(b.values())
                inputs = (only_a or only_b)[0][0]
                step = DiffStep(dict(zip(proj.inputs, inputs)),
                                dict(zip(proj.observables, only_a[0][1])) if a else None,
                                dict(zip(proj.observables, only_b[0][1])) if b else None)
                return trace_to(parent, step)
        raise AssertionError("label sets differ but no input's observations do")

    def expand(o: int, m: int, parent: int) -> list[DiffStep] | None:
        nonlocal nondet
        so, vo, no = orig.signature(o)
        sm, vm, nm = mut.signature(m)
        nondet = nondet or no or nm
        if so.keys() != sm.keys():
            return differing(o, m, parent)
        for lab, targets in so.items():
            mts = sm[lab]
            step = (vo[lab], vm[lab])
            for o2 in targets:
                for m2 in mts:
                    if (o2, m2) not in seen:
                        seen.add((o2, m2))
                        pairs.append((o2, m2))
                        parents.append(parent)
                        via.append(step)
        return None

    diff = expand(-1, -1, -1)  # the initial states
    if diff is not None:
        return ProductResult("difference", 0, diff, nondet)
    k = 0
    while k < len(pairs):
        if k >= max_pairs or (deadline is not None and k % 256 == 0 and time.process_time() > deadline):
            why = f"{k} pairs expanded, {len(pairs) - k} left" + (
                " (pair budget)" if k >= max_pairs else " (time budget)")
            return ProductResult("timeout", k, nondeterministic=nondet, reason=why)
        o, m = pairs[k]
        diff = expand(o, m, k)
        if diff is not None:
            return ProductResult("difference", k + 1, diff, nondet)
        k += 1
    return ProductResult("equivalent", k, nondeterministic=nondet)


def _grouped(g: LabelledGraph, i: int) -> dict[tuple, dict[tuple, Label]]:
    """State i's steps (-1: the initial states) by input, then observation, as the
    search compares them (copied positions None), each with a label it stands for
    (Python values)."""
    out: dict[tuple, dict[tuple, Label]] = {}
    for vid, _d, mk in dict.fromkeys(g.steps(i)):
        inp, obs = g.masked(vid, mk)
        out.setdefault(inp, {}).setdefault(obs, g.label(vid))
    return out


def confirm(original: Model, mutant: Model, proj: Projection, steps: list[DiffStep],
            max_frontier: int = 20_000) -> list[DiffStep] | None:
    """The difference trace `steps` (found on stored states) replayed on the exact states
    of both models with the Python engine: the pairs reachable by its inputs with its
    observations, and at the last step a pair whose observations for its input differ.
    Returns the trace with that last step (None: not confirmed, or the replay grew past
    `max_frontier` pairs)."""
    ii, oi = proj.indices(original)
    mi, mo = proj.indices(mutant)

    def pick(st: tuple, ix: tuple[int, ...]) -> tuple:
        return tuple(st[i] for i in ix)

    def succ(model: Model, st: tuple) -> list[tuple]:
        return list(dict.fromkeys(t.state for t in model.successors(st) if model.in_model(t.state)))

    def matching(sts: list[tuple], ix: tuple[int, ...], ox: tuple[int, ...], s: DiffStep, obs: dict | None) -> list:
        want_i = tuple(s.inputs[k] for k in proj.inputs)
        want_o = None if obs is None else tuple(obs[k] for k in proj.observables)
        return [t for t in sts if pick(t, ix) == want_i and (want_o is None or pick(t, ox) == want_o)]

    if len(steps) == 1:
        return steps  # the initial states: recorded exactly
    first = steps[0]
    frontier = [(o, m) for o in matching([s for s in original.initial_states() if original.in_model(s)], ii, oi,
                                         first, first.original)
                for m in matching([s for s in mutant.initial_states() if mutant.in_model(s)], mi, mo,
                                  first, first.mutant)]
    for s in steps[1:-1]:
        nxt: dict[tuple, None] = {}
        for o, m in frontier:
            for o2 in matching(succ(original, o), ii, oi, s, s.original):
                for m2 in matching(succ(mutant, m), mi, mo, s, s.mutant):
                    nxt[(o2, m2)] = None
        if not nxt or len(nxt) > max_frontier:
            return None
        frontier = list(nxt)
    last = steps[-1]
    for o, m in frontier:
        a = {pick(t, oi) for t in matching(succ(original, o), ii, oi, last, None)}
        b = {pick(t, mo) for t in matching(succ(mutant, m), mi, mo, last, None)}
        if a != b:
            only_a, only_b = sorted(a - b, key=repr), sorted(b - a, key=repr)
            oa = only_a[0] if only_a else (next(iter(a)) if a else None)
            ob = only_b[0] if only_b else (next(iter(b)) if b else None)
            return steps[:-1] + [DiffStep(last.inputs, None if oa is None else dict(zip(proj.observables, oa)),
                                          None if ob is None else dict(zip(proj.observables, ob)))]
    return None
