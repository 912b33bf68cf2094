"""Reading S6 pile pull-out results (used by tools/plot_s6.py and test/python/test_s6.py):
head load-displacement curve, shaft stresses, interpolation at a common load."""
import h5py
import numpy as np

Q_END = 6.28   # kN at pattern factor 1 (tools/make_s6_decks.py)


def head_curve(path):
    """(head pull [kN], head uplift [m, upwards +]) for every written increment, from 0."""
    with h5py.File(path) as f:
        x = f["mesh/coordinates"][:]
        centre = np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1]) < 1e-9))[0][0]
        rows = np.nonzero(f["history/fields"][:])[0]
        load = f["history/pattern_factors"][:, 0][rows] * Q_END
        keys = sorted(f["increments"].keys())
        u = np.array([f["increments"][k]["displacement"][centre, 1] for k in keys])
    return np.r_[0.0, load], np.r_[0.0, u]


def uplift_at(path, q):
    """Head uplift [m] at the pull q [kN] (linear between increments); nan beyond the curve."""
    load, u = head_curve(path)
    return float(np.interp(q, load, u)) if q <= load[-1] + 1e-12 else float("nan")


def shaft(path, key):
    """depths of the shaft points (z < 0), (sigma_n, tau) [kPa] there, modes."""
    with h5py.File(path) as f:
        pc = f["mesh/joint_sets/shaft/point_coordinates"][:]
        g = f["increments"][key]["joints/shaft"]
        return pc[:, :, 1].ravel(), g["stress"][:].reshape(-1, 2), g["mode"][:].ravel()


def keys_and_loads(path):
    with h5py.File(path) as f:
        keys = sorted(f["increments"].keys())
        rows = np.nonzero(f["history/fields"][:])[0]
        return keys, f["history/pattern_factors"][:, 0][rows] * Q_END
