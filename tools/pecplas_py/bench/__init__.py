"""Benchmark scripts of `make bench` (tools/bench.sh runs each as python3 -m pecplas_py.bench.NAME)
and their shared helpers (common.py, wp_*.py); results in doc/bench/."""
