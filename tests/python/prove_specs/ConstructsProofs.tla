------------------------- MODULE ConstructsProofs -------------------------
EXTENDS Constructs
Strengthen_QUEUE == FromIds
=============================================================================
