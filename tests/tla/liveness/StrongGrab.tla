---------------------------- MODULE StrongGrab ----------------------------
(* A token is offered intermittently (Flip toggles "offered"); Grab may    *)
(* take it only while it is offered.  SF on Grab guarantees the token is  *)
(* grabbed; the property is the quantified form over two customers.       *)
(* Expected: success.                                                     *)
CONSTANT Customers
VARIABLES offered, holder
vars == <<offered, holder>>
Init == offered = FALSE /\ holder = "nobody"
Flip == offered' = ~offered /\ UNCHANGED holder
Grab(c) == offered /\ holder = "nobody" /\ holder' = c /\ UNCHANGED offered
Release(c) == holder = c /\ holder' = "nobody" /\ UNCHANGED offered
Next == Flip \/ \E c \in Customers : Grab(c) \/ Release(c)
Spec == Init /\ [][Next]_vars /\ WF_vars(Flip)
        /\ \A c \in Customers : SF_vars(Grab(c)) /\ WF_vars(Release(c))

EveryoneServed == \A c \in Customers : []<>(holder = c)
=============================================================================
