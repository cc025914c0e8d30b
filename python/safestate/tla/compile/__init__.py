"""The expression compiler's families, one module each (a mixin composed into
`tla.compiler.Compiler`, plus the run-time helpers its closures use)."""
