---------------------------- MODULE BoundedFifo ----------------------------
(***************************************************************************)
(* A producer sends values through a bounded FIFO to a consumer that       *)
(* remembers the last value it took out.  The producer cycles through the  *)
(* kinds red, green, blue, so the consumer can check the FIFO order: the   *)
(* head of the buffer must always be the successor of what it last got.    *)
(*                                                                         *)
(* Exercises: INSTANCE WITH substituting a variable and two constants      *)
(* (one by an expression), Seq(S) in a membership test, Len, Head, Tail,   *)
(* Append, <<A>>_v and [A]_v inside Next, CASE with OTHER, a CONSTANT set  *)
(* of strings.                                                             *)
(* Expected: success.  The [Receive]_vars disjunct allows stuttering, so   *)
(* stuttering steps are counted in "states generated".                     *)
(***************************************************************************)
EXTENDS Naturals, Sequences

CONSTANTS Kinds, N

VARIABLES buf, nextKind, lastRecv

vars == <<buf, nextKind, lastRecv>>

Chan == INSTANCE Channel WITH q <- buf, Msg <- Kinds, Cap <- N + 1

\* The kinds in a fixed cyclic order.
Succ(k) == CASE k = "red"   -> "green"
             [] k = "green" -> "blue"
             [] OTHER       -> "red"

Init ==
    /\ Chan!ChanInit
    /\ nextKind = "red"
    /\ lastRecv = "none"

Produce ==
    /\ Chan!Send(nextKind)
    /\ nextKind' = Succ(nextKind)
    /\ UNCHANGED lastRecv

Receive ==
    /\ Chan!CanRecv
    /\ lastRecv' = Head(buf)
    /\ Chan!Recv
    /\ UNCHANGED nextKind

Next == <<Produce>>_vars \/ [Receive]_vars

Spec == Init /\ [][Next]_vars

TypeOK ==
    /\ Chan!ChanTypeOK
    /\ nextKind \in Kinds
    /\ lastRecv \in Kinds \cup {"none"}

\* The head of the buffer is the successor of what was received last.
InOrder == (buf /= << >> /\ lastRecv /= "none") => Head(buf) = Succ(lastRecv)
=============================================================================
