"""Scenes S1-S6 of doc/validation.md (make s1 ... s6): readers of their results (sN_results),
figures (plot_sN), the generated blocks of the docs (sN_report) and stored references."""
