"""Specs shared by the `safestate mutate` tests."""

# `note` is observed, outside the VIEW and kept from step to step: a stored state can
# carry another value of it than the state it stands for (graph.confirm).
VIEWED = r"""---- MODULE Viewed ----
EXTENDS Naturals
VARIABLES inp, h, note
View == <<inp, h>>
Init == inp = 0 /\ h = 0 /\ note = "a"
Next == \E i \in {0, 1} :
    /\ inp' = i
    /\ h' = IF i = 1 THEN 0 ELSE h
    /\ note' = IF i = 1 THEN "b" ELSE note
TypeOK == inp \in 0..1 /\ h \in 0..1 /\ note \in {"a", "b"}
====
"""

# Reachability witnesses (mutate/witness.py): Witness_Alarm is reached by input 2 only;
# Witness_Never is never reached by the original (reported, not used).  Safe pins
# `alarm` to input 2 one way only, so a mutant that never raises the alarm passes it.
WITNESSED = r"""---- MODULE Witnessed ----
EXTENDS Naturals
VARIABLES inp, alarm
Init == inp = 0 /\ alarm = FALSE
Next == \E i \in {0, 1, 2} :
    /\ inp' = i
    /\ alarm' = (i = 2)
TypeOK == inp \in 0..2 /\ alarm \in BOOLEAN
Safe == alarm => inp = 2
Witness_Alarm == ~alarm
Witness_Never == inp # 7
====
"""

# Witness_Hot reads Hot, which the behaviour uses too: a mutant of Hot must not change
# what the witness asks (input 2 read), only what the model does with it.
WITNESS_READS_BEHAVIOUR = r"""---- MODULE HotWitness ----
EXTENDS Naturals
VARIABLES inp, alarm
Hot(i) == i = 2
Init == inp = 0 /\ alarm = FALSE
Next == \E i \in {0, 1, 2} :
    /\ inp' = i
    /\ alarm' = Hot(i)
TypeOK == inp \in 0..2 /\ alarm \in BOOLEAN
Safe == alarm => inp = 2
Witness_Hot == ~Hot(inp)
====
"""

# Poke keeps the inputs, and the VIEW leaves out `free`: a stored state of class
# <<1, FALSE, 1>> is the original's (1, 1, FALSE, 1) but the mutant's (seen never set)
# (1, 0, FALSE, 1), first reached by another input -- their Poke steps carry different
# `free` values, though after any one input trace both sides hold the same (graph.py,
# "Carried values under a VIEW").
CARRIED = r"""---- MODULE Carried ----
EXTENDS Naturals
VARIABLES inp, free, seen, out
View == <<inp, seen, out>>
Init == inp = 0 /\ free = 0 /\ seen = FALSE /\ out = 0
Tick == \E i \in {0, 1}, f \in {0, 1} :
    /\ inp' = i
    /\ free' = f
    /\ seen' = (seen \/ f = 0)
    /\ out' = i
Poke == /\ UNCHANGED <<inp, free, seen>>
        /\ out' = 2
Next == Tick \/ Poke
TypeOK == inp \in 0..1 /\ free \in 0..1 /\ seen \in BOOLEAN /\ out \in 0..2
====
"""
