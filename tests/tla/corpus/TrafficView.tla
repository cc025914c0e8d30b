---------------------------- MODULE TrafficView ----------------------------
(***************************************************************************)
(* A traffic light with a queue of cars, plus an auxiliary step counter    *)
(* `ticks` that records how many steps were taken (modulo 10).  The        *)
(* counter is irrelevant to the behaviour, so the cfg declares a VIEW that *)
(* leaves it out: TLC then identifies states that agree on the view, and   *)
(* "distinct states" counts distinct views.                                *)
(*                                                                         *)
(* Exercises: VIEW, CASE without OTHER (all arms covered), a tuple-valued  *)
(* view, UNCHANGED of a single variable and of a tuple.                    *)
(* Expected: success, with 12 distinct states (3 colours x 4 queue         *)
(* lengths) instead of the 120 there would be without the VIEW.            *)
(***************************************************************************)
EXTENDS Naturals

CONSTANT MaxCars

VARIABLES light, cars, ticks

Init == light = "red" /\ cars = 0 /\ ticks = 0

Tick == ticks' = (ticks + 1) % 10

Change ==
    /\ light' = CASE light = "red"    -> "green"
                  [] light = "green"  -> "yellow"
                  [] light = "yellow" -> "red"
    /\ Tick
    /\ UNCHANGED cars

Arrive ==
    /\ cars < MaxCars
    /\ cars' = cars + 1
    /\ Tick
    /\ UNCHANGED light

Pass ==
    /\ light = "green"
    /\ cars > 0
    /\ cars' = cars - 1
    /\ Tick
    /\ UNCHANGED <<light>>

Next == Change \/ Arrive \/ Pass

View == <<light, cars>>

TypeOK == /\ light \in {"red", "green", "yellow"}
          /\ cars \in 0..MaxCars
          /\ ticks \in 0..9
=============================================================================
