"""Generators of the numbers quoted in doc/validation.md and doc/theory.md from the test suites
and dedicated runs (make docs)."""
