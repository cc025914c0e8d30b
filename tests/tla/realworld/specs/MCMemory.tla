------------------------------ MODULE MCMemory ------------------------------
(* An internal memory in the style of Specifying Systems' InternalMemory, *)
(* with the operator constants Send/Reply substituted in the .cfg by      *)
(* operators of four arguments (Send <- MCSend) whose last argument is    *)
(* memInt': the substituted operator assigns it, as TLC expands it.       *)
(* Also: NoVal = NoVal overrides an unbounded CHOOSE.  TLC: success.      *)
EXTENDS MemoryInterface
VARIABLES mem, ctl, buf
MCSend(p, d, oldMemInt, newMemInt) == newMemInt = <<p, d>>
MCReply(p, d, oldMemInt, newMemInt) == newMemInt = <<p, d>>
MCInitMemInt == {<<CHOOSE p \in Proc : TRUE, NoVal>>}
Init == /\ mem \in [Adr -> Val]
        /\ ctl = [p \in Proc |-> "rdy"]
        /\ buf = [p \in Proc |-> NoVal]
        /\ memInt \in InitMemInt
TypeInvariant == /\ mem \in [Adr -> Val]
                 /\ ctl \in [Proc -> {"rdy", "busy", "done"}]
                 /\ buf \in [Proc -> MReq \cup Val \cup {NoVal}]
Req(p) == /\ ctl[p] = "rdy"
          /\ \E req \in MReq : /\ Send(p, req, memInt, memInt')
                               /\ buf' = [buf EXCEPT ![p] = req]
                               /\ ctl' = [ctl EXCEPT ![p] = "busy"]
          /\ UNCHANGED mem
Do(p) == /\ ctl[p] = "busy"
         /\ mem' = IF buf[p].op = "Wr" THEN [mem EXCEPT ![buf[p].adr] = buf[p].val] ELSE mem
         /\ buf' = [buf EXCEPT ![p] = IF buf[p].op = "Wr" THEN NoVal ELSE mem[buf[p].adr]]
         /\ ctl' = [ctl EXCEPT ![p] = "done"]
         /\ UNCHANGED memInt
Rsp(p) == /\ ctl[p] = "done"
          /\ Reply(p, buf[p], memInt, memInt')
          /\ ctl' = [ctl EXCEPT ![p] = "rdy"]
          /\ UNCHANGED <<mem, buf>>
Next == \E p \in Proc : Req(p) \/ Do(p) \/ Rsp(p)
Spec == Init /\ [][Next]_<<memInt, mem, ctl, buf>>
=============================================================================
