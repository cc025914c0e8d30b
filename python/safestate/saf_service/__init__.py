"""The Safety service as processes (docs/design/safety-service.md §14): `safestate saf serve`
(the C++ service host behind the binding safestate._saf_net, with its configuration file,
log and signals) and the Safety Client and subsystem simulators, each its own process."""
