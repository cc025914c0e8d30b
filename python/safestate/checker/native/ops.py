"""Op codes of the native core's program tree, and what each node holds.

Generated from bindings/python/tla_native/ops.def by scripts/gen_native_ops.py: edit
ops.def and run the script (tests/python/test_native_ops_table.py fails when this file
and ops.def differ).  At import the names are compared with the compiled core's.
"""

from __future__ import annotations

from enum import IntEnum

from ... import _tla_native as core


class Op(IntEnum):
    # expressions: leaves and scopes
    CONST = 0  # a constant: v
    VAR = 1  # a variable of the current state: ints[0] its index
    PVAR = 2  # a primed variable (the successor being built): ints[0] its index
    SLOT = 3  # a bound name's slot: ints[0]
    LETREF = 4  # a LET definition or lazy argument, evaluated at its first use: ints[0] its slot; kids[0]
    LET = 5  # LET ... IN: ints the definitions' slots (reset); kids[0] the body
    # expressions: booleans, integers
    NOT = 6  # ~ kids[0] (folded when constant)
    NEG = 7  # - kids[0] (folded when constant)
    AND = 8  # the conjunction of kids, left to right (folded when constant)
    OR = 9  # the disjunction of kids, left to right (folded when constant)
    IMPLIES = 10  # kids[0] => kids[1] (folded when constant)
    EQUIV = 11  # kids[0] <=> kids[1] (folded when constant)
    EQ = 12  # kids[0] = kids[1] (folded when constant)
    NEQ = 13  # kids[0] /= kids[1] (folded when constant)
    LT = 14  # kids[0] < kids[1] (folded when constant)
    LE = 15  # kids[0] <= kids[1] (folded when constant)
    GT = 16  # kids[0] > kids[1] (folded when constant)
    GE = 17  # kids[0] >= kids[1] (folded when constant)
    ADD = 18  # kids[0] + kids[1] (folded when constant)
    SUB = 19  # kids[0] - kids[1] (folded when constant)
    MUL = 20  # kids[0] * kids[1] (folded when constant)
    DIV = 21  # kids[0] \div kids[1] (folded when constant)
    MOD = 22  # kids[0] % kids[1] (folded when constant)
    # expressions: sets
    RANGE = 23  # kids[0] .. kids[1] (folded when constant)
    IN = 24  # kids[0] \in kids[1] (a set value) (folded when constant)
    NOTIN = 25  # kids[0] \notin kids[1] (a set value) (folded when constant)
    CUP = 26  # kids[0] \cup kids[1] (folded when constant)
    CAP = 27  # kids[0] \cap kids[1] (folded when constant)
    DIFF = 28  # kids[0] \ kids[1] (folded when constant)
    SUBSETEQ = 29  # kids[0] \subseteq kids[1] (folded when constant)
    # expressions: control and quantifiers
    IF = 30  # IF kids[0] THEN kids[1] ELSE kids[2] (folded when constant)
    CASE = 31  # CASE: ints[0] arms; kids guard, value per arm, then OTHER if any (folded when constant)
    FORALL = 32  # \A x \in kids[0] : kids[1]; ints[0] x's slot (folded when constant)
    EXISTS = 33  # \E x \in kids[0] : kids[1]; ints[0] x's slot (folded when constant)
    SETENUM = 34  # {kids...} (folded when constant)
    SETFILTER = 35  # {x \in kids[0] : kids[1]}; ints[0] x's slot (folded when constant)
    SETMAP = 36  # {kids[n] : x1 \in kids[0], ...}; ints one slot per binder (folded when constant)
    # expressions: functions, records, tuples, sequences
    FNAPP = 37  # kids[0][kids[1]] (folded when constant)
    FNLIT = 38  # [x \in kids[0] |-> kids[1]]; ints[0] x's slot (folded when constant)
    RECLIT = 39  # [f1 |-> kids[0], ...]; ints the field names' ids (folded when constant)
    TUPLE = 40  # <<kids...>> (folded when constant)
    # [kids[0] EXCEPT ![k..] = v, ...]; ints the @ slot, then each update's path depth; kids the base, then each
    # update's keys and value (folded when constant)
    EXCEPT = 41
    AT = 42  # @ in an EXCEPT value: ints[0] its slot
    DOMAIN = 43  # DOMAIN kids[0] (folded when constant)
    LEN = 44  # Len(kids[0]) (folded when constant)
    HEAD = 45  # Head(kids[0]) (folded when constant)
    TAIL = 46  # Tail(kids[0]) (folded when constant)
    APPEND = 47  # Append(kids[0], kids[1]) (folded when constant)
    CONCAT = 48  # kids[0] \o kids[1] (folded when constant)
    SUBSEQ = 49  # SubSeq(kids[0], kids[1], kids[2]) (folded when constant)
    CARD = 50  # Cardinality(kids[0]) (folded when constant)
    # kids[0] \in (ints[0] 0) or \notin (1) the set described by kids[1] (an SD_ node) (folded when constant)
    IN_SD = 51
    BIND = 52  # an operator call: kids the arguments, evaluated into the slots ints, then the body (last kid)
    RECSET = 53  # [f1 : kids[0], ...] as a finite set of records; ints the field names' ids (folded when constant)
    # set descriptors (membership only, never enumerated)
    SD_SET = 54  # the set value kids[0]
    SD_RANGE = 55  # kids[0] .. kids[1]
    SD_SEQ = 56  # Seq(kids[0])
    SD_FN = 57  # [kids[0] -> kids[1]]
    SD_REC = 58  # [f1 : kids[0], ...]; ints the field names' ids
    SD_NAT = 59  # Nat
    SD_INT = 60  # Int
    SD_STRING = 61  # STRING
    # actions (continuation-passing: k is what follows)
    A_EMIT = 62  # a successor (or initial state) is complete: ints[0] the action leaf
    A_FALSE = 63  # no successor
    A_GUARD = 64  # kids[0] must hold, then k
    A_OR = 65  # each disjunct in kids, in order
    A_EXISTS = 66  # \E over an action: ints one slot per binder; kids the binders' sets, then the body
    A_LET = 67  # LET in an action: ints the definitions' slots (reset); kids[0] the body
    A_ASSIGN = 68  # x' = kids[0]: ints[0] x's index; then k
    # x' \in kids[0] (enumerated) or kids[1] (a descriptor, when x' is assigned): ints[0] x's index; then k
    A_ASSIGN_IN = 69
    A_IF = 70  # IF kids[0] THEN action kids[1] ELSE action kids[2]
    A_CASE = 71  # CASE over actions: as CASE
    A_IMPLIES = 72  # kids[0] => action kids[1]; k when kids[0] is false
    A_ALLASSIGNED = 73  # kids[0] while a variable is unassigned, else kids[1]
    A_BIND = 74  # an operator call in an action: as BIND, the body an action
    # more set descriptors
    SD_CUP = 75  # kids[0] \cup kids[1]
    SD_CAP = 76  # kids[0] \cap kids[1]
    SD_DIFF = 77  # kids[0] \ kids[1]
    # more expressions
    CHOOSE = 78  # CHOOSE x \in kids[0] : kids[1]; ints[0] x's slot
    SELECTSEQ = 79  # SelectSeq(kids[0], test): ints[0] the test's parameter slot; kids[1] its body
    # an operator call whose body reads only its parameters: as BIND, its value remembered per argument values
    BIND_MEMO = 80
    TOSTRING = 81  # ToString(kids[0]): the value as TLC prints it (folded when constant)
    # \A over an action that branches: the conjunction of its instances
    # ints the \A's index, the first and one past the last slot its body uses, the binders' slots; kids the binders'
    # sets, the body as an action, the body as a guard, the A_FORALL_NEXT both end in; k what follows
    A_FORALL = 82
    A_FORALL_NEXT = 83  # goes on to the next instance of the A_FORALL k
    # SUBSET S, S1 \X S2 \X ..., [S -> T] as finite sets (as values: enumerated)
    POWERSET = 84  # SUBSET kids[0] (folded when constant)
    PRODUCT = 85  # kids[0] \X kids[1] \X ... (folded when constant)
    FNSET = 86  # [kids[0] -> kids[1]] (folded when constant)
    # membership in SUBSET S, S1 \X S2 ...
    SD_SUBSET = 87  # SUBSET kids[0]
    SD_PRODUCT = 88  # kids[0] \X kids[1] \X ...


if tuple(Op.__members__) != tuple(core.OP_NAMES):
    raise ImportError("checker/native/ops.py is out of step with the compiled native core "
                      "(rebuild it: scripts/setup.sh; or regenerate ops.py: scripts/gen_native_ops.py)")
