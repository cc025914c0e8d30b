------------------------ MODULE TerminationDetection ------------------------
(* Dijkstra's EWD840 termination detection on a ring: a token with a      *)
(* colour travels from node N-1 down to 0; nodes activate each other.    *)
(* Constructs: records as the token, functions of colours, IF inside      *)
(* EXCEPT, \A over a range in the invariant.  TLC: success.               *)
EXTENDS Naturals
CONSTANT N
Node == 0 .. N - 1
Color == {"white", "black"}
VARIABLES active, color, tpos, tcolor
vars == <<active, color, tpos, tcolor>>
Init == /\ active \in [Node -> BOOLEAN]
        /\ color = [i \in Node |-> "white"]
        /\ tpos = 0
        /\ tcolor = "black"
InitiateProbe == /\ tpos = 0
                 /\ tcolor = "black" \/ color[0] = "black"
                 /\ tpos' = N - 1
                 /\ tcolor' = "white"
                 /\ active' = active
                 /\ color' = [color EXCEPT ![0] = "white"]
PassToken(i) == /\ tpos = i
                /\ ~active[i] \/ color[i] = "black" \/ tcolor = "black"
                /\ tpos' = i - 1
                /\ tcolor' = IF color[i] = "black" THEN "black" ELSE tcolor
                /\ active' = active
                /\ color' = [color EXCEPT ![i] = "white"]
SendMsg(i) == /\ active[i]
              /\ \E j \in Node \ {i} :
                    /\ active' = [active EXCEPT ![j] = TRUE]
                    /\ color' = [color EXCEPT ![i] = IF j > i THEN "black" ELSE @]
              /\ UNCHANGED <<tpos, tcolor>>
Deactivate(i) == /\ active[i]
                 /\ active' = [active EXCEPT ![i] = FALSE]
                 /\ UNCHANGED <<color, tpos, tcolor>>
Next == \/ InitiateProbe
        \/ \E i \in Node \ {0} : PassToken(i)
        \/ \E i \in Node : SendMsg(i) \/ Deactivate(i)
Spec == Init /\ [][Next]_vars /\ WF_vars(Next)
TypeOK == /\ active \in [Node -> BOOLEAN] /\ color \in [Node -> Color]
          /\ tpos \in Node /\ tcolor \in Color
terminationDetected == /\ tpos = 0 /\ tcolor = "white"
                       /\ color[0] = "white" /\ ~active[0]
TerminationDetection == terminationDetected => \A i \in Node : ~active[i]
=============================================================================
