#!/usr/bin/env python3
"""Picture of a PECPLAS results file (`make run`): the installed program pecplas-plot
(pecplas_py/programs/pecplas_plot.py, which stands alone), run from the source tree: the
deformed mesh coloured by a field over the whole model, the plastic Gauss points, and the
load-displacement curve of the node or set the step is controlled by (force, pressure,
imposed displacement or arc-length stop node).

    python3 -m pecplas_py.plots.plot_results output/default.h5 [-o out.png] [--field syy]
                                                 [--increment N] [--scale S] ...
(`--component xx|yy|zz|xy` is still understood; `--help` lists the rest.)"""
import sys

from pecplas_py.programs.pecplas_plot import main

if __name__ == "__main__":
    sys.exit(main())
