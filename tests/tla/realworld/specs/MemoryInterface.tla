--------------------------- MODULE MemoryInterface ---------------------------
(* The memory interface of Specifying Systems ch. 5: Send and Reply are   *)
(* operator CONSTANTS, given values by a model (MCMemory).  Not checked  *)
(* on its own.                                                            *)
CONSTANTS Send(_, _, _, _), Reply(_, _, _, _), InitMemInt, Proc, Adr, Val
VARIABLE memInt
MReq == [op : {"Rd"}, adr : Adr] \cup [op : {"Wr"}, adr : Adr, val : Val]
NoVal == CHOOSE v : v \notin Val
=============================================================================
