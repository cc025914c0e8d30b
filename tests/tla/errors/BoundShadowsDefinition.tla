---- MODULE BoundShadowsDefinition ----
(* The bound variable of Next's \E reuses the name of the definition Foo.  *)
(* SANY: "Multiply-defined symbol 'Foo'" at line 8 (issue 27 item 3), exit *)
(* 150; a bound variable may not reuse a name visible where it is bound.   *)
VARIABLE x
Foo == 1
Init == x \in {Foo}
Next == \E Foo \in {1, 2} : x' = Foo
====
