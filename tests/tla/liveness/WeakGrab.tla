---------------------------- MODULE WeakGrab ----------------------------
(* A token is offered intermittently (Flip toggles "offered"); Grab may    *)
(* take it only while it is offered.  WF on Grab is not enough: Grab is  *)
(* never continuously enabled, so a customer may never be served.        *)
(* Expected: temporal property violated.                                 *)
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

EveryoneServed == \A c \in Customers : []<>(holder = c)
=============================================================================
