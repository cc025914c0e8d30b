-------------------------- MODULE KeyValueStore --------------------------
(* A key-value store with snapshot-isolated transactions, in the style of *)
(* the KeyValueStore example: a store as a function Key -> Val \cup       *)
(* {NoVal}, per-transaction snapshots and write sets.  Constructs:        *)
(* functions, [S -> T] membership in TypeOK, EXCEPT, set of keys,         *)
(* function construction over a filter.  TLC: success.                    *)
CONSTANTS Key, Val, TxId, NoVal
VARIABLES store, tx, snapshot, written
vars == <<store, tx, snapshot, written>>
Store == [Key -> Val \cup {NoVal}]
Init == /\ store = [k \in Key |-> NoVal]
        /\ tx = {}
        /\ snapshot = [t \in TxId |-> [k \in Key |-> NoVal]]
        /\ written = [t \in TxId |-> {}]
TypeOK == /\ store \in Store
          /\ tx \subseteq TxId
          /\ snapshot \in [TxId -> Store]
          /\ written \in [TxId -> SUBSET Key]
OpenTx(t) == /\ t \notin tx
             /\ tx' = tx \cup {t}
             /\ snapshot' = [snapshot EXCEPT ![t] = store]
             /\ UNCHANGED <<written, store>>
Write(t, k, v) == /\ t \in tx
                  /\ snapshot' = [snapshot EXCEPT ![t][k] = v]
                  /\ written' = [written EXCEPT ![t] = @ \cup {k}]
                  /\ UNCHANGED <<tx, store>>
Commit(t) == /\ t \in tx
             /\ \A k \in written[t] : store[k] = snapshot[t][k] \/ store[k] = NoVal
             /\ store' = [k \in Key |-> IF k \in written[t] THEN snapshot[t][k] ELSE store[k]]
             /\ tx' = tx \ {t}
             /\ written' = [written EXCEPT ![t] = {}]
             /\ UNCHANGED snapshot
Abort(t) == /\ t \in tx
            /\ tx' = tx \ {t}
            /\ written' = [written EXCEPT ![t] = {}]
            /\ UNCHANGED <<snapshot, store>>
Next == \E t \in TxId : OpenTx(t) \/ Commit(t) \/ Abort(t) \/ \E k \in Key, v \in Val : Write(t, k, v)
Spec == Init /\ [][Next]_vars
WrittenInSnapshot == \A t \in tx : \A k \in written[t] : snapshot[t][k] # NoVal
=============================================================================
