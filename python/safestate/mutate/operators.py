"""The mutation operators: each turns one node of a definition's syntax tree into
zero or more edits (a byte range of the file and its replacement text).

The tree is tree-sitter-tlaplus's concrete syntax tree, the one `safestate.tla.parser`
converts to the typed AST: only the concrete tree carries the exact byte range of every
construct, which a textual substitution needs.  Every operator is first-order (one
change) and keeps the module well-formed; changes that can only yield an ill-formed
state (dropping a conjunct that assigns a primed variable, `x' = e` turned into
`x' # e`) are not generated, so that nearly every mutant is a behaviour, not an error.

The table of operators, with an example each, is in docs/mutate.md.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field

from tree_sitter import Node


@dataclass(frozen=True)
class Edit:
    start: int          # byte offsets in the file
    end: int
    replacement: str
    what: str           # one line: what the edit does


@dataclass
class Context:
    """What an operator may need beyond the node: the file's bytes, the definition being
    mutated and its role."""

    data: bytes
    definition: str
    is_next: bool = False       # the cfg's NEXT definition
    is_init: bool = False       # the cfg's INIT definition
    # Byte ranges of the set expressions the environment draws inputs from (the bounds of
    # the \E of Next, and the definitions they name): `drop-input-value` works inside them.
    input_sets: list[tuple[int, int]] = field(default_factory=list)
    # The input variables (system.toml [mutate] inputs): `unchanged` leaves their
    # assignments alone (an input frozen is `drop-input-value`'s business).
    inputs: frozenset[str] = frozenset()

    def text(self, n: Node) -> str:
        return self.data[n.start_byte:self.end(n)].decode("utf-8")

    def column(self, byte: int) -> int:
        return byte - (self.data.rfind(b"\n", 0, byte) + 1)

    def compose(self, start: int, parts: Iterable[str | Node]) -> str:
        """The replacement text of an edit beginning at byte `start`: the strings as
        they are, each node's text placed so that its lines keep their columns relative
        to its first where it holds a junction list of several lines (whose bullets
        must stay aligned, or it parses as another expression, or not at all).  Such a
        node that would begin left of its own column is padded to it; one that would
        begin right of it has its later lines moved right as far.  Any other text is
        placed as it is (column-insensitive)."""
        out: list[str] = []
        col = self.column(start)
        for part in parts:
            if isinstance(part, str):
                piece = part
            else:
                piece = self.text(part)
                if _has_bullets(piece):
                    own = self.column(part.start_byte)
                    if col < own:
                        out.append(" " * (own - col))
                        col = own
                    elif col > own:
                        piece = piece.replace("\n", "\n" + " " * (col - own))
            out.append(piece)
            nl = piece.rfind("\n")
            col = col + len(piece.encode()) if nl < 0 else len(piece[nl + 1:].encode())
        return "".join(out)

    def end(self, n: Node) -> int:
        """Where the node's text ends: the grammar lets the last item of a list run on over
        the comments and blank lines after it, which an edit must keep (else the next
        definition is glued to the replacement, or commented out)."""
        end = n.end_byte
        while True:
            body = self.data[n.start_byte:end].rstrip()
            end = n.start_byte + len(body)
            nl = body.rfind(b"\n")
            if nl < 0 or not body[nl + 1:].lstrip().startswith(b"\\*"):
                return end
            end = n.start_byte + nl  # a comment-only last line: not the node's


def _has_bullets(text: str) -> bool:
    """Whether `text` spans lines of a junction list (a line beginning with a bullet)."""
    lines = text.split("\n")
    return len(lines) > 1 and any(x.lstrip().startswith(("/\\", "\\/")) for x in lines)


@dataclass(frozen=True)
class Operator:
    name: str
    summary: str
    fn: Callable[[Node, Context], Iterator[Edit]]

    @property
    def doc(self) -> str:
        return (self.fn.__doc__ or "").strip()


_RELATION_SWAP = {"lt": ("<", "<="), "leq": ("<=", "<"), "gt": (">", ">="), "geq": (">=", ">"),
                  "eq": ("=", "#"), "neq": ("#", "=")}
_RELATION_SYMBOLS = {"lt", "leq", "gt", "geq", "eq", "neq"}


def _named(n: Node) -> list[Node]:
    return [c for c in n.named_children if c.type != "comment" and c.type != "block_comment"]


def _infix_parts(n: Node) -> tuple[Node, Node, Node] | None:
    """(lhs, symbol, rhs) of a `bound_infix_op`."""
    if n.type != "bound_infix_op":
        return None
    k = _named(n)
    if len(k) != 3:
        return None
    return k[0], k[1], k[2]


def _is_infix(n: Node, symbol: str) -> bool:
    p = _infix_parts(n)
    return p is not None and p[1].type == symbol


def _strip_parens(n: Node) -> Node:
    while n.type == "parentheses" and _named(n):
        n = _named(n)[0]
    return n


def _mentions_prime(n: Node) -> bool:
    """True when the subtree sets or reads a primed variable (x', UNCHANGED, [A]_v)."""
    if n.type in ("prime", "unchanged"):
        return True
    return any(_mentions_prime(c) for c in n.children)


def _is_primed_name(n: Node) -> bool:
    n = _strip_parens(n)
    if n.type != "bound_postfix_op":
        return False
    k = _named(n)
    return len(k) == 2 and k[1].type == "prime" and k[0].type == "identifier_ref"


def _conjuncts(n: Node) -> list[Node] | None:
    """The items of a conjunction: a bulleted list or an infix chain, flattened."""
    if n.type == "conj_list":
        return [_named(i)[-1] for i in _named(n) if i.type == "conj_item"]
    if _is_infix(n, "land"):
        out: list[Node] = []
        stack = [n]
        while stack:
            x = stack.pop()
            p = _infix_parts(x)
            if p is not None and p[1].type == "land":
                stack.extend((p[2], p[0]))
            else:
                out.append(x)
        return out
    return None


def _disjuncts(n: Node) -> list[Node] | None:
    if n.type == "disj_list":
        return [_named(i)[-1] for i in _named(n) if i.type == "disj_item"]
    if _is_infix(n, "lor"):
        out: list[Node] = []
        stack = [n]
        while stack:
            x = stack.pop()
            p = _infix_parts(x)
            if p is not None and p[1].type == "lor":
                stack.extend((p[2], p[0]))
            else:
                out.append(x)
        return out
    return None


def _is_chain_top(n: Node) -> bool:
    """An infix /\\ or \\/ node inside a chain of the same operator is not the chain's top."""
    par = n.parent
    if par is None or par.type != "bound_infix_op":
        return True
    p = _infix_parts(par)
    return p is None or p[1].type != _infix_parts(n)[1].type  # type: ignore[index]


def _if_parts(n: Node) -> tuple[Node, Node, Node]:
    return (n.child_by_field_name("if"), n.child_by_field_name("then"),  # type: ignore[return-value]
            n.child_by_field_name("else"))


# ------------------------------------------------------------------ the operators

def drop_conjunct(n: Node, ctx: Context) -> Iterator[Edit]:
    """Drop one conjunct of a conjunction: the conjunct becomes TRUE (a guard not
    tested, a requirement not imposed).  Conjuncts that set a primed variable are left
    to `unchanged` (dropping them leaves the successor undefined, an error, not a
    behaviour)."""
    items = _conjuncts(n)
    if items is None or len(items) < 2 or (n.type == "bound_infix_op" and not _is_chain_top(n)):
        return
    for it in items:
        if _mentions_prime(it) or ctx.is_init:
            continue
        yield Edit(it.start_byte, ctx.end(it), "TRUE", f"conjunct `{_short(ctx.text(it))}` dropped")


def negate_condition(n: Node, ctx: Context) -> Iterator[Edit]:
    """Negate a condition: the condition of an IF, or the guard of a CASE arm, becomes
    ~(condition)."""
    if n.type == "if_then_else":
        c = _if_parts(n)[0]
        yield Edit(c.start_byte, ctx.end(c), ctx.compose(c.start_byte, ["~(", c, ")"]),
                   f"IF condition `{_short(ctx.text(c))}` negated")
    elif n.type == "case_arm":
        c = _named(n)[0]
        yield Edit(c.start_byte, ctx.end(c), ctx.compose(c.start_byte, ["~(", c, ")"]),
                   f"CASE guard `{_short(ctx.text(c))}` negated")


def move_boundary(n: Node, ctx: Context) -> Iterator[Edit]:
    """Move a relational boundary: < and <= swapped, > and >= swapped, = and #
    swapped.  Not on an assignment x' = e, nor in the initial predicate (x # 0 there
    is an unbounded initial state)."""
    p = _infix_parts(n)
    if p is None or p[1].type not in _RELATION_SYMBOLS:
        return
    lhs, sym, rhs = p
    if sym.type in ("eq", "neq") and (ctx.is_init or _mentions_prime(lhs) or _mentions_prime(rhs)):
        return
    old, new = _RELATION_SWAP[sym.type]
    yield Edit(sym.start_byte, ctx.end(sym), new, f"`{old}` became `{new}`")


def literal_step(n: Node, ctx: Context) -> Iterator[Edit]:
    """A numeric literal +1 or -1 (never below 0: the models use Naturals)."""
    if n.type != "nat_number":
        return
    v = int(ctx.text(n))
    yield Edit(n.start_byte, ctx.end(n), str(v + 1), f"{v} became {v + 1}")
    if v > 0:
        yield Edit(n.start_byte, ctx.end(n), str(v - 1), f"{v} became {v - 1}")


def swap_if(n: Node, ctx: Context) -> Iterator[Edit]:
    """Swap the THEN and ELSE branches of an IF."""
    if n.type != "if_then_else":
        return
    c, t, e = _if_parts(n)
    text = ctx.compose(n.start_byte, ["IF ", c, " THEN ", e, " ELSE ", t])
    yield Edit(n.start_byte, ctx.end(n), text, f"branches of IF `{_short(ctx.text(c))}` swapped")


def delete_arm(n: Node, ctx: Context) -> Iterator[Edit]:
    """Delete one arm of a CASE (at least one arm stays), or one step of an
    IF/ELSE IF priority chain (`IF c THEN a ELSE rest` becomes `rest`)."""
    if n.type == "case":
        arms = [c for c in _named(n) if c.type in ("case_arm", "other_arm")]
        if len(arms) < 2:
            return
        for i, arm in enumerate(arms):
            rest = [a for j, a in enumerate(arms) if j != i]
            guards = [a for a in rest if not ctx.text(a).lstrip().startswith("OTHER")]
            other = [a for a in rest if ctx.text(a).lstrip().startswith("OTHER")]
            if not guards:
                continue
            parts: list[str | Node] = ["CASE "]
            for k, a in enumerate(guards + other):
                parts += [" [] ", a] if k else [a]
            text = ctx.compose(n.start_byte, parts)
            yield Edit(n.start_byte, ctx.end(n), text, f"CASE arm `{_short(ctx.text(arm))}` deleted")
    elif n.type == "if_then_else" and _in_chain(n):
        c, _, e = _if_parts(n)
        yield Edit(n.start_byte, ctx.end(n), ctx.compose(n.start_byte, [e]),
                   f"priority step IF `{_short(ctx.text(c))}` deleted")


def _in_chain(n: Node) -> bool:
    """An IF that is a step of an IF/ELSE IF chain: its ELSE is an IF, or it is one's ELSE."""
    e = _strip_parens(_if_parts(n)[2])
    par = n.parent
    return e.type == "if_then_else" or (par is not None and par.type == "if_then_else"
                                        and par.child_by_field_name("else") == n)


def swap_steps(n: Node, ctx: Context) -> Iterator[Edit]:
    """Swap two adjacent steps of an IF/ELSE IF priority chain:
    `IF c1 THEN a ELSE IF c2 THEN b ELSE r` becomes `IF c2 THEN b ELSE IF c1 THEN a ELSE r`."""
    if n.type != "if_then_else":
        return
    c1, a, e = _if_parts(n)
    inner = _strip_parens(e)
    if inner.type != "if_then_else":
        return
    c2, b, r = _if_parts(inner)
    text = ctx.compose(n.start_byte, ["IF ", c2, " THEN ", b, " ELSE IF ", c1, " THEN ", a, " ELSE ", r])
    yield Edit(n.start_byte, ctx.end(n), text,
               f"priority steps `{_short(ctx.text(c1))}` and `{_short(ctx.text(c2))}` swapped")


def unchanged(n: Node, ctx: Context) -> Iterator[Edit]:
    """Replace a primed assignment by the unchanged value: `x' = e` becomes `x' = x`
    (an output not set, a latch not latched, a counter frozen)."""
    p = _infix_parts(n)
    if p is None or p[1].type != "eq" or not _is_primed_name(p[0]):
        return
    var = ctx.text(_named(_strip_parens(p[0]))[0])
    if ctx.text(p[2]).strip() == var or var in ctx.inputs:
        return
    yield Edit(p[2].start_byte, ctx.end(p[2]), var, f"{var}' kept unchanged (was `{_short(ctx.text(p[2]))}`)")


def drop_except_update(n: Node, ctx: Context) -> Iterator[Edit]:
    """Drop one update of an EXCEPT: `[f EXCEPT !.a = 1, !.b = 2]` loses `!.a = 1`
    (with one update only, the EXCEPT becomes `f`)."""
    if n.type != "except":
        return
    kids = _named(n)
    base, updates = kids[0], [k for k in kids[1:] if k.type == "except_update"]
    for i, u in enumerate(updates):
        rest = [x for j, x in enumerate(updates) if j != i]
        parts: list[str | Node] = ["[", base, " EXCEPT "]
        for k, x in enumerate(rest):
            parts += [", ", x] if k else [x]
        text = ctx.compose(n.start_byte, parts + ["]"] if rest else ["(", base, ")"])
        yield Edit(n.start_byte, ctx.end(n), text, f"EXCEPT update `{_short(ctx.text(u))}` dropped")


def drop_next_disjunct(n: Node, ctx: Context) -> Iterator[Edit]:
    """Delete one disjunct of Next (the cfg's NEXT definition): that step is never taken."""
    if not ctx.is_next:
        return
    items = _disjuncts(n)
    if items is None or len(items) < 2 or (n.type == "bound_infix_op" and not _is_chain_top(n)):
        return
    for it in items:
        yield Edit(it.start_byte, ctx.end(it), "FALSE", f"disjunct `{_short(ctx.text(it))}` of Next deleted")


def drop_input_value(n: Node, ctx: Context) -> Iterator[Edit]:
    """Remove one value from a set the environment draws an input from (a bound of an
    \\E in Next, or a definition that bound names): an element of a set literal, one
    of BOOLEAN, or an end of a range a..b.  An input never offered."""
    if not any(s <= n.start_byte and n.end_byte <= e for s, e in ctx.input_sets):
        return
    if n.type == "finite_set_literal":
        elems = _named(n)
        if len(elems) < 2:
            return
        for i, el in enumerate(elems):
            rest = [ctx.text(x) for j, x in enumerate(elems) if j != i]
            yield Edit(n.start_byte, ctx.end(n), "{" + ", ".join(rest) + "}",
                       f"input value {_short(ctx.text(el))} never offered")
    elif n.type == "boolean_set":
        yield Edit(n.start_byte, ctx.end(n), "{TRUE}", "input value FALSE never offered")
        yield Edit(n.start_byte, ctx.end(n), "{FALSE}", "input value TRUE never offered")
    else:
        p = _infix_parts(n)
        if p is not None and p[1].type == "dots_2":
            lo, hi = ctx.text(p[0]), ctx.text(p[2])
            yield Edit(n.start_byte, ctx.end(n), f"(({lo}) + 1)..({hi})", f"input value {lo} of {lo}..{hi} never offered")
            yield Edit(n.start_byte, ctx.end(n), f"({lo})..(({hi}) - 1)", f"input value {hi} of {lo}..{hi} never offered")


def _short(s: str, width: int = 60) -> str:
    s = " ".join(s.split())
    return s if len(s) <= width else s[:width - 3] + "..."


OPERATORS: dict[str, Operator] = {op.name: op for op in (
    Operator("drop-conjunct", "drop one conjunct of a conjunction", drop_conjunct),
    Operator("negate", "negate a condition (IF, CASE guard)", negate_condition),
    Operator("boundary", "move a relational boundary (< <=, > >=, = #)", move_boundary),
    Operator("literal", "a numeric literal +1 / -1", literal_step),
    Operator("swap-if", "swap the branches of an IF", swap_if),
    Operator("delete-arm", "delete one CASE arm or one step of an IF/ELSE IF chain", delete_arm),
    Operator("swap-steps", "swap two adjacent steps of an IF/ELSE IF chain", swap_steps),
    Operator("unchanged", "a primed assignment x' = e becomes x' = x", unchanged),
    Operator("drop-except", "drop one update of an EXCEPT", drop_except_update),
    Operator("drop-disjunct", "delete one disjunct of Next", drop_next_disjunct),
    Operator("drop-input-value", "remove one value from a set an input is drawn from", drop_input_value),
)}
