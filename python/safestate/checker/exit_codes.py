"""TLC's process exit codes (tlc2.output.EC.ExitStatus), which we reuse."""

SUCCESS = 0
VIOLATION_ASSUMPTION = 10
VIOLATION_DEADLOCK = 11
VIOLATION_SAFETY = 12
VIOLATION_LIVENESS = 13
VIOLATION_ASSERT = 14        # TLC!Assert failed
FAILURE_SPEC_EVAL = 75       # evaluation error while computing states
FAILURE_SAFETY_EVAL = 76     # evaluation error in an invariant
ERROR_SPEC_PARSE = 150       # syntax or semantic error in a module
ERROR_CONFIG_PARSE = 151     # bad .cfg, unknown names, unsupported constructs (as TLC's "can't handle")
ERROR_SYSTEM = 153           # memory limit reached
ERROR = 255                  # internal error
USAGE = 2                    # an unusable argument (unwritable --itf/--graph): `safestate --help`
SECOND_OPINION_DISAGREES = 1  # `--tlc`: TLC's verdict or counts differ from ours
SECOND_OPINION_FAILED = 3    # `--tlc`: TLC could not be run (TLA2TOOLS_JAR not a working jar)
OUTPUT_FAILED = 74           # stdout, --itf or --graph could not be written (sysexits' EX_IOERR)
INTERRUPTED = 130            # Ctrl-C (128 + SIGINT)
TERMINATED = 143             # SIGTERM (128 + SIGTERM)

BY_KIND = {
    "syntax": ERROR_SPEC_PARSE,
    "semantic": ERROR_SPEC_PARSE,
    "config": ERROR_CONFIG_PARSE,
    "cfg syntax": ERROR,
    "unsupported": ERROR_CONFIG_PARSE,
    "eval": FAILURE_SPEC_EVAL,
    "module eval": ERROR,        # a standard module's error while computing successors (Head(<<>>))
    "temporal": ERROR,           # a property TLC's liveness checker refuses (EC.TLC_LIVE_*), as TLC
    "invariant eval": FAILURE_SAFETY_EVAL,
    # TLC's replay of the state for the call stack met a second error (explore.py): 75
    "invariant eval, replay failed": FAILURE_SPEC_EVAL,
    "assert": VIOLATION_ASSERT,
    "assumption": VIOLATION_ASSUMPTION,
    "memory": ERROR_SYSTEM,
    "integer too big": ERROR,    # a numeral beyond 32 bits: TLC's EC.TLC_INTEGER_TOO_BIG has no exit status of its own
    "general": ERROR,            # TLC's Assert.fail(message): EC.GENERAL, exit 255
}

BY_RESULT = {
    "success": SUCCESS,
    "safety failure": VIOLATION_SAFETY,
    "deadlock failure": VIOLATION_DEADLOCK,
    # TLC exits with VIOLATION_LIVENESS for every kind of PROPERTY violation.
    "liveness failure": VIOLATION_LIVENESS,
    # A temporal property's finite counterexample, where TLC stops its search (12).
    "temporal safety failure": VIOLATION_SAFETY,
    "action property failure": VIOLATION_LIVENESS,
    "init property failure": VIOLATION_LIVENESS,
}
