"""Reading S2/S3 pile results (used by tools/plot_s2.py and the tests): head load-settlement
curve, shaft stresses, shaft shear resultant."""
import h5py
import numpy as np

A = 0.5            # pile radius [m]
HEAD_LOAD = 2000.0  # kN at factor 1


def head_curve(path):
    """(head load [kN], head settlement [m, downwards +]) for every written increment."""
    with h5py.File(path) as f:
        x = f["mesh/coordinates"][:]
        centre = np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1]) < 1e-9))[0][0]
        rows = np.nonzero(f["history/fields"][:])[0]
        load = f["history/pattern_factors"][:, 0][rows] * HEAD_LOAD
        keys = sorted(f["increments"].keys())
        s = np.array([-f["increments"][k]["displacement"][centre, 1] for k in keys])
        steps = f["history/step"][:][rows]
    return load, s, steps


def shaft(path, key):
    """z of the shaft points, (sigma_n, tau), modes, and the shaft shear resultant [kN]
    (Gauss points of 2-point joints, or springs weighted by their tributary area)."""
    with h5py.File(path) as f:
        js = f["mesh/joint_sets/shaft"]
        pc = js["point_coordinates"][:]
        g = f["increments"][key]["joints/shaft"]
        s = g["stress"][:]
        mode = g["mode"][:]
        if "tributary" in js:
            w = js["tributary"][:].reshape(s.shape[:2])
        else:
            rule = js.attrs["integration"]
            rule = rule.decode() if isinstance(rule, bytes) else rule
            z = pc[:, :, 1]
            # 2 points per element: Lobatto at the ends, Gauss at +-1/sqrt(3); weight h/2 each
            h = np.abs(z[:, 0] - z[:, 1]) * (np.sqrt(3.0) if rule == "GAUSS" else 1.0)
            w = np.repeat(h[:, None] / 2.0, 2, axis=1) * 2.0 * np.pi * A
        q = float(np.sum(s[:, :, 1] * w))
    return pc[:, :, 1].ravel(), s.reshape(-1, 2), mode.ravel(), q


def last_key(path, step):
    with h5py.File(path) as f:
        keys = sorted(f["increments"].keys())
        return max(k for k in keys if int(f["increments"][k].attrs["step"]) == step)
