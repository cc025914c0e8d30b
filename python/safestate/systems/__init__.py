"""The system registry: one manifest per state machine (`systems/<Name>/system.toml`)
naming its design page, models, proof plan, C++ binding, conformance adapter and
requirement IDs.  `safestate systems` lists them; the other subcommands accept a
system name wherever they take a model path.  See docs/adding-a-system.md."""
