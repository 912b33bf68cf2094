"""Reading S6 pile pull-out results (used by scenes/plot_s6.py and test/python/test_s6.py):
head load-displacement curve, shaft stresses, interpolation at a common load."""
import numpy as np

from pecplas_py.results import Results

Q_END = 6.28   # kN at pattern factor 1 (decks/make_s6_decks.py)


def _head_nodes(x):
    """The pile head's nodes: at z = 0 with r <= the pile radius (the sand's node at r = a is
    free, its reaction zero)."""
    return np.nonzero((np.abs(x[:, 1]) < 1e-9) & (x[:, 0] <= 0.0275 + 1e-9))[0]


def head_curve(path):
    """(head pull [kN], head uplift [m, upwards +]) for every written increment, from 0. The
    pull is the head reaction when the uplift is imposed (MODJOIN decks), else the pressure
    pattern's factor times Q_END (Mohr-Coulomb deck)."""
    with Results(path) as r:
        x = r.coordinates
        centre = np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1]) < 1e-9))[0][0]
        head = _head_nodes(x)
        u = r.fields("displacement")[:, centre, 1]
        react = r.fields("reaction")[:, head, 1].sum(axis=1)
        imposed = "TYPE=DISPLACEMENT" in r.deck_text
        load = react if imposed else r.pattern_factors(r.field_rows())[:, 0] * Q_END
    return np.r_[0.0, load], np.r_[0.0, u]


def uplift_at(path, q):
    """Head uplift [m] at the pull q [kN] on the last rising branch of the curve (past the early
    local peak of MODJOIN's imposed-uplift runs, linear between increments); nan if the run
    never carries q."""
    load, u = head_curve(path)
    if q > load.max() + 1e-12:
        return float("nan")
    i = len(load) - 1 - int(np.argmax(load[::-1] < q))   # last increment below q
    if load[i] >= q:
        return float(np.interp(q, load, u))
    if i == len(load) - 1:
        return float("nan")   # the curve ends below q, on a falling branch
    j = i + 1
    return float(u[i] + (u[j] - u[i]) * (q - load[i]) / (load[j] - load[i]))


def shaft(path, key):
    """depths of the shaft points (z < 0), (sigma_n, tau) [kPa] there, modes."""
    with Results(path) as r:
        pc = r.joint_set("shaft")["point_coordinates"][:]
        return (pc[:, :, 1].ravel(), r.field(key, "joints/shaft/stress").reshape(-1, 2),
                r.field(key, "joints/shaft/mode").ravel())


def keys_and_loads(path):
    """Increment keys and the head pull [kN] at each."""
    with Results(path) as r:
        keys = r.keys
    return keys, head_curve(path)[0][1:]
