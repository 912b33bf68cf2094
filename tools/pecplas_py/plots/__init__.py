"""Figures of any results file (plot_results: make run) or pecplas-path CSV (plot_path)."""
