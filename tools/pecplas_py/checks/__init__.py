"""Checks of results and inputs: check_results (a results file against doc/results.md),
mutate_decks (deck fuzzer), mpi_check (MUMPS on 1 and 2 ranks against the serial solvers)."""
