--------------------------- MODULE GrabNotStrong ---------------------------
(* The token of WeakGrab (only weak fairness on Grab), checked against the *)
(* PROPERTY that Grab is strongly fair for every customer: it is not, as  *)
(* the token is offered infinitely often without being grabbed.           *)
(* Expected: temporal property violated.                                  *)
CONSTANT Customers
VARIABLES offered, holder
vars == <<offered, holder>>
Init == offered = FALSE /\ holder = "nobody"
Flip == offered' = ~offered /\ UNCHANGED holder
Grab(c) == offered /\ holder = "nobody" /\ holder' = c /\ UNCHANGED offered
Release(c) == holder = c /\ holder' = "nobody" /\ UNCHANGED offered
Next == Flip \/ \E c \in Customers : Grab(c) \/ Release(c)
Spec == Init /\ [][Next]_vars /\ WF_vars(Flip)
        /\ \A c \in Customers : WF_vars(Grab(c)) /\ WF_vars(Release(c))

ReleaseWeaklyFair == \A c \in Customers : WF_vars(Release(c))
GrabStronglyFair == \A c \in Customers : SF_vars(Grab(c))
=============================================================================
