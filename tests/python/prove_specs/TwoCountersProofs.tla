------------------------- MODULE TwoCountersProofs -------------------------
EXTENDS TwoCounters
Strengthen_SYNC == x = y
=============================================================================
