"""Grammar 3 of the generator: the constructs of the supported subset that grammars
1 and 2 never produce.

Expressions: EXCEPT with nested paths (``![i].f``, ``!.h[i]``) on records of sets
and functions, ``UNION``, ``\\E <<x, y>> \\in S \\X T``, recursive functions in LET,
a RECURSIVE operator, ``SelectSeq`` with a LAMBDA, ``Seq(S)`` membership, sets of
model values.  Spec level (see `generator.generate`): several initial states by
disjunction, IF inside a prime, priming of operator parameters, SYMMETRY, VIEW,
ACTION_CONSTRAINT, and SPECIFICATION with WF/SF fairness and PROPERTY liveness
(``<>P``, ``[]<>P``, ``<>[]P``, ``P ~> Q``, ``[][A]_v``).

Grammars 1 and 2 draw the same random numbers as before, so their specs are
unchanged: every extension here is reached only through `Gen3`.
"""

from __future__ import annotations

from .generator import BOOL, INT, MOD, SEQ, SET, Gen

NEST, PSET = "nest", "pset"  # a record [s |-> set of ints, h |-> function], a set of model values
PROCS = ["p1", "p2", "p3"]
ERROR_SHARE = 0.04  # grammar 4: the share of SUBSET/\\X operands left bare


class Gen3(Gen):
    """Grammar 3: every expression kind of `Gen`, plus the forms above."""

    def __init__(self, rng, grammar: int) -> None:
        super().__init__(rng, grammar)
        self.features: set[str] = set()
        self.symmetric = False  # no CHOOSE over Procs when SYMMETRY is used
        self.recursive = False  # the RECURSIVE operator SumS is defined

    def use(self, feature: str) -> None:
        self.features.add(feature)

    # ------------------------------------------------------------ new types
    def e_nest(self, d: int) -> str:
        vs = self.vars_of(NEST)
        if d <= 0 or self.chance(0.3) or not vs:
            if vs and self.chance(0.6):
                return self.pick(vs)
            k = self.name("k")
            return f"[s |-> {self.e_set(0)}, h |-> [{k} \\in {{1, 2}} |-> {self.r.randint(0, 2)}]]"
        base = self.e_nest(d - 1)
        i = self.r.randint(1, 2)
        self.use("except_nested_path")
        form = self.r.randint(0, 3)
        if form == 0:
            return f"[{base} EXCEPT !.h[{i}] = (@ + 1) % 3]"
        if form == 1:
            return f"[{base} EXCEPT !.s = (@ \\cup {{({self.e_int(d - 1)}) % {MOD}}})]"
        if form == 2:
            return f"[{base} EXCEPT !.s = @ \\ {{{self.r.randint(0, 3)}}}, !.h[{i}] = ({self.e_int(d - 1)}) % 3]"
        return f"[{base} EXCEPT !.h = [@ EXCEPT ![{i}] = 2 - @]]"

    def e_pset(self, d: int) -> str:
        vs = self.vars_of(PSET)
        if d <= 0 or self.chance(0.3):
            return self.pick(["{}", "Procs", "{p1}"] + vs)
        self.use("model_values")
        base = self.e_pset(d - 1)
        if self.symmetric:  # only forms that treat every model value alike
            return self.pick([f"({base} \\cup {self.e_pset(d - 1)})", f"({base} \\cap {self.e_pset(d - 1)})",
                              f"(Procs \\ {base})"])
        k = self.r.randint(0, 3)
        if k == 0:
            return f"({base} \\cup {{{self.proc()}}})"
        if k == 1:
            return f"({base} \\ {{{self.proc()}}})"
        if k == 2:
            q = self.name("q")
            return f"{{{q} \\in {base} : {q} # {self.proc()}}}"
        return f"(Procs \\ {base})"

    def operand(self, s: str) -> str:
        """Grammar 4 parenthesises the operand of SUBSET and \\X: written bare, SANY reads
        `SUBSET 0..2` as `(SUBSET 0)..2`, `{2} \\X 0..2` as `({2} \\X 0)..2`, and rejects
        `UNION S \\X T`, so about 18% of grammar 3's specs end in a TLC error.  A few
        (ERROR_SHARE) stay bare, so that errors are still compared."""
        if self.grammar < 4 or self.chance(ERROR_SHARE):
            return s
        return f"({s})"

    def proc(self) -> str:
        """A model value (never used when `symmetric`)."""
        if self.chance(0.2):
            return "(CHOOSE q \\in Procs : TRUE)"
        return self.pick(PROCS)

    # ------------------------------------------------------------ extended kinds
    def e_int(self, d: int) -> str:
        if d > 0 and self.chance(0.25):
            k = self.r.randint(0, 5)
            if k == 0 and self.vars_of(NEST):
                return f"{self.e_nest(d - 1)}.h[{self.r.randint(1, 2)}]"
            if k == 1 and self.vars_of(NEST):
                return f"Cardinality({self.e_nest(d - 1)}.s)"
            if k == 2:
                self.use("let_recursive_function")
                f, n = self.name("r"), self.name("n")
                body = self._with(n, INT, lambda: f"(({f}[{n} - 1] + {self.e_int(d - 1)}) % {MOD})")
                return (f"(LET {f}[{n} \\in 0..3] == IF {n} = 0 THEN {self.e_int(0)} ELSE {body} "
                        f"IN {f}[({self.e_int(d - 1)}) % 4])")
            if k == 3 and self.recursive:
                self.use("recursive_operator")
                return f"(SumS({self.e_set(d - 1)}) % {MOD})"
            if k == 4 and self.vars_of(PSET):
                return f"Cardinality({self.e_pset(d - 1)})"
            if k == 5:
                self.use("seq_ops")
                z = self.name("z")
                return f"Len(SelectSeq({self.e_seq(d - 1)}, LAMBDA {z} : {z} > {self.r.randint(0, 2)}))"
        return super().e_int(d)

    def e_bool(self, d: int) -> str:
        if d > 0 and self.chance(0.25):
            k = self.r.randint(0, 4)
            if k == 0:
                self.use("tuple_binder")
                x, y = self.name("x"), self.name("y")
                quant = self.pick(["\\E", "\\A"])
                body = self._with(x, INT, lambda: self._with(y, INT, lambda: self.e_bool(d - 1)))
                left = self.operand(self.e_set(d - 1))
                return f"({quant} <<{x}, {y}>> \\in {left} \\X {self.operand(self.e_set(0))} : {body})"
            if k == 1 and self.vars_of(NEST):
                return f"({self.e_int(d - 1)} \\in {self.e_nest(d - 1)}.s)"
            if k == 2 and self.vars_of(PSET):
                w = self.name("w")
                if self.symmetric:
                    return f"(\\E {w} \\in Procs : {w} \\in {self.e_pset(d - 1)})"
                return f"({self.proc()} \\in {self.e_pset(d - 1)})"
            if k == 3:
                self.use("seq_ops")
                return f"({self.e_seq(d - 1)} \\in Seq({{0, 1}}))"
            if k == 4 and self.vars_of(NEST):
                return f"({self.e_nest(d - 1)} = {self.e_nest(d - 1)})"
        return super().e_bool(d)

    def e_set(self, d: int) -> str:
        if d > 0 and self.chance(0.2):
            self.use("union")
            return f"UNION {{{self.e_set(d - 1)}, {self.e_set(d - 1)}}}"
        return super().e_set(d)

    def e_seq(self, d: int) -> str:
        if d > 0 and self.chance(0.15):
            self.use("seq_ops")
            s = self.e_seq(d - 1)
            j = self.name("j")
            return f"[{j} \\in 1..Len({s}) |-> ({s}[{j}] + 1) % 3]"
        return super().e_seq(d)

    def init_value(self, ty: str) -> tuple[str, str]:
        if ty == NEST:
            return self.pick([("=", "[s |-> {}, h |-> [k \\in {1, 2} |-> 0]]"),
                              ("\\in", "[s : {{}, {1}}, h : [{1, 2} -> 0..1]]")])
        if ty == PSET:
            return self.pick([("=", "{}"), ("\\in", "{{}, {p1}, {p1, p2}}")])
        return super().init_value(ty)


RECURSIVE_SUM = ["RECURSIVE SumS(_)",
                 "SumS(S) == IF S = {} THEN 0 ELSE LET y == CHOOSE z \\in S : TRUE IN y + SumS(S \\ {y})"]
TYPES3 = [INT, BOOL, "str", SET, SEQ, "rec", "fun", NEST, PSET]
