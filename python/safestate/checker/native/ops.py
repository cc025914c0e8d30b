"""Op codes of the native core's program tree, in the order of `enum Op` in
bindings/python/tla_native_module.cpp (checked against the module at import)."""

from __future__ import annotations

from enum import IntEnum

from ... import _tla_native as core


class Op(IntEnum):
    CONST = 0
    VAR = 1
    PVAR = 2
    SLOT = 3
    LETREF = 4
    LET = 5
    NOT = 6
    NEG = 7
    AND = 8
    OR = 9
    IMPLIES = 10
    EQUIV = 11
    EQ = 12
    NEQ = 13
    LT = 14
    LE = 15
    GT = 16
    GE = 17
    ADD = 18
    SUB = 19
    MUL = 20
    DIV = 21
    MOD = 22
    RANGE = 23
    IN = 24
    NOTIN = 25
    CUP = 26
    CAP = 27
    DIFF = 28
    SUBSETEQ = 29
    IF = 30
    CASE = 31
    FORALL = 32
    EXISTS = 33
    SETENUM = 34
    SETFILTER = 35
    SETMAP = 36
    FNAPP = 37
    FNLIT = 38
    RECLIT = 39
    TUPLE = 40
    EXCEPT = 41
    AT = 42
    DOMAIN = 43
    LEN = 44
    HEAD = 45
    TAIL = 46
    APPEND = 47
    CONCAT = 48
    SUBSEQ = 49
    CARD = 50
    IN_SD = 51
    BIND = 52
    RECSET = 53
    SD_SET = 54
    SD_RANGE = 55
    SD_SEQ = 56
    SD_FN = 57
    SD_REC = 58
    SD_NAT = 59
    SD_INT = 60
    SD_STRING = 61
    A_EMIT = 62
    A_FALSE = 63
    A_GUARD = 64
    A_OR = 65
    A_EXISTS = 66
    A_LET = 67
    A_ASSIGN = 68
    A_ASSIGN_IN = 69
    A_IF = 70
    A_CASE = 71
    A_IMPLIES = 72
    A_ALLASSIGNED = 73
    A_BIND = 74
    SD_CUP = 75
    SD_CAP = 76
    SD_DIFF = 77
    CHOOSE = 78
    SELECTSEQ = 79
    BIND_MEMO = 80
    TOSTRING = 81
    A_FORALL = 82
    A_FORALL_NEXT = 83
    POWERSET = 84
    PRODUCT = 85
    FNSET = 86
    SD_SUBSET = 87
    SD_PRODUCT = 88


assert (core.OP_COUNT, core.OP_IN_SD, core.OP_SD_STRING, core.OP_A_BIND, core.OP_SELECTSEQ,
        core.OP_BIND_MEMO, core.OP_TOSTRING, core.OP_A_FORALL_NEXT, core.OP_SD_PRODUCT) == (
            len(Op), Op.IN_SD, Op.SD_STRING, Op.A_BIND, Op.SELECTSEQ, Op.BIND_MEMO, Op.TOSTRING, Op.A_FORALL_NEXT,
            Op.SD_PRODUCT), \
    "checker/native/ops.py is out of step with the C++ core"
