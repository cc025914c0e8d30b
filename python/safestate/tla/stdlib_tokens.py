"""The words of TLC's standard modules (TLC 1.8.0, tla2sany/StandardModules) in the
order SANY interns them, with the modules each one extends and instantiates.

TLC orders strings by when they were interned; a spec's string that is also a word of
a standard module it uses (e.g. "a" in Naturals) gets the rank of that word.  Generated
from the module texts with `parser._token_order`; the standard modules have no string
literals, except TLCExt's "Assertion failed" (left out: it only matters to a spec that
uses that very string)."""

from __future__ import annotations

# name -> (EXTENDS, INSTANCE, words in order of first appearance)
STANDARD_TOKENS: dict[str, tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]] = {
    'Naturals': ((), (), (
        'MODULE', 'Naturals', 'Nat', 'a', 'b', 'CHOOSE', 'n', 'TRUE',
    )),
    'Integers': (('Naturals',), (), (
        'MODULE', 'Integers', 'EXTENDS', 'Naturals', 'Int', 'a',
    )),
    'Sequences': ((), ('Naturals',), (
        'MODULE', 'Sequences', 'LOCAL', 'INSTANCE', 'Naturals', 'Seq', 'S', 'UNION', 'n',
        'Nat', 'Len', 's', 'CHOOSE', 'DOMAIN', 't', 'i', 'IF', 'THEN', 'ELSE', 'Append',
        'e', 'Head', 'Tail', 'CASE', 'SubSeq', 'm', 'SelectSeq', 'Test', 'LET', 'F', 'IN',
    )),
    'FiniteSets': ((), ('Naturals', 'Sequences'), (
        'MODULE', 'FiniteSets', 'LOCAL', 'INSTANCE', 'Naturals', 'Sequences',
        'IsFiniteSet', 'S', 'seq', 'Seq', 's', 'n', 'Len', 'Cardinality', 'LET', 'CS', 'T',
        'SUBSET', 'IF', 'THEN', 'ELSE', 'CHOOSE', 'x', 'IN',
    )),
    'TLC': ((), ('Naturals', 'Sequences', 'FiniteSets'), (
        'MODULE', 'TLC', 'LOCAL', 'INSTANCE', 'Naturals', 'Sequences', 'FiniteSets',
        'Print', 'out', 'val', 'PrintT', 'TRUE', 'Assert', 'IF', 'THEN', 'ELSE', 'CHOOSE',
        'v', 'JavaTime', 'n', 'Nat', 'TLCGet', 'i', 'TLCSet', 'd', 'e', 'x', 'f', 'g',
        'DOMAIN', 'Permutations', 'S', 'w', 'SortSeq', 's', 'Op', 'LET', 'Perm', 'p',
        'Len', 'j', 'IN', 'RandomElement', 'Any', 'ToString', 'a', 'b', 'STRING',
        'TLCEval',
    )),
    'Bags': (('TLC',), ('Naturals',), (
        'MODULE', 'Bags', 'EXTENDS', 'TLC', 'LOCAL', 'INSTANCE', 'Naturals', 'IsABag', 'B',
        'DOMAIN', 'n', 'Nat', 'BagToSet', 'SetToBag', 'S', 'e', 'BagIn', 'EmptyBag', 'B1',
        'B2', 'IF', 'THEN', 'ELSE', 'LET', 'IN', 'd', 'Sum', 'f', 'DSum', 'SUBSET', 'elt',
        'CHOOSE', 'TRUE', 'BagUnion', 'UNION', 'SubBag', 'RemoveFromDom', 'x', 'y',
        'Combine', 'BagSet', 'i', 'Biggest', 'Range', 'r', 's', 'RSB', 'BB', 'SB',
        'AllBagsOfSubset', 'BagOfAll', 'F', 'BagCardinality', 'CopiesIn', 'Apr',
        'Modified', 'version', 'for', 'standard', 'module', 'set', 'Dec', 'Corrected',
        'error', 'found', 'by', 'Stephan', 'Merz', 'comments', 'based', 'on',
        'suggestions', 'Lyle', 'Ramshaw', 'Initial',
    )),
    # Its one string literal, "Assertion failed", is not listed (see the docstring).
    'TLCExt': ((), ('TLC', 'Integers'), (
        'MODULE', 'TLCExt', 'LOCAL', 'INSTANCE', 'TLC', 'Integers', 'AssertEq', 'a', 'b', 'IF',
        'THEN', 'PrintT', 'ELSE', 'AssertError', 'err', 'exp', 'LET', 'FailsEval', 'e', 'CHOOSE',
        'BOOLEAN', 'TRUE', 'TLCError', 's', 'STRING', 'IN', 'Assert', 'TLCGetOrDefault', 'key',
        'defaultVal', 'n', 'TLCGetAndSet', 'Op', 'val', 'oldVal', 'v', 'TLCSet', 'Trace',
        'CounterExample', 'ToTrace', 'CE', 'TLCModelValue', 'str', 'ToString', 'TLCDefer',
        'expression', 'TLCNoOp', 'PickSuccessor', 'bool', 'TLCCache', 'closure', 'TLCFP', 'var',
        'i', 'Int', 'TLCEvalDefinition', 'definitionName',
    )),
}
