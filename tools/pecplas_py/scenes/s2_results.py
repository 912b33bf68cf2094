"""Reading S2/S3 pile results (used by scenes/plot_s2.py and the tests): head load-settlement
curve, shaft stresses, shaft shear resultant."""
import numpy as np

from pecplas_py.results import Results, text

A = 0.5            # pile radius [m]
HEAD_LOAD = 2000.0  # kN at factor 1


def head_curve(path):
    """(head load [kN], head settlement [m, downwards +]) for every written increment."""
    with Results(path) as r:
        x = r.coordinates
        centre = np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1]) < 1e-9))[0][0]
        rows = r.field_rows()
        load = r.pattern_factors(rows)[:, 0] * HEAD_LOAD
        s = -r.fields("displacement")[:, centre, 1]
        steps = r.history("step")[rows]
    return load, s, steps


def shaft(path, key):
    """z of the shaft points, (sigma_n, tau), modes, and the shaft shear resultant [kN]
    (Gauss points of 2-point joints, or springs weighted by their tributary area)."""
    with Results(path) as r:
        js = r.joint_set("shaft")
        pc = js["point_coordinates"][:]
        s = r.field(key, "joints/shaft/stress")
        mode = r.field(key, "joints/shaft/mode")
        if "tributary" in js:
            w = js["tributary"][:].reshape(s.shape[:2])
        else:
            rule = text(js.attrs["integration"])
            z = pc[:, :, 1]
            # 2 points per element: Lobatto at the ends, Gauss at +-1/sqrt(3); weight h/2 each
            h = np.abs(z[:, 0] - z[:, 1]) * (np.sqrt(3.0) if rule == "GAUSS" else 1.0)
            w = np.repeat(h[:, None] / 2.0, 2, axis=1) * 2.0 * np.pi * A
        q = float(np.sum(s[:, :, 1] * w))
    return pc[:, :, 1].ravel(), s.reshape(-1, 2), mode.ravel(), q


def last_key(path, step):
    with Results(path) as r:
        return r.last_key(step)


def settlement_at(path, load):
    """Head settlement [m] at `load` [kN] on the loading branch (step 1), interpolated."""
    q, s, steps = head_curve(path)
    m = steps == 1
    return float(np.interp(load, np.r_[0.0, q[m]], np.r_[0.0, s[m]]))


def load_at(path, settlement):
    """Head load [kN] at head settlement `settlement` [m] on the loading branch."""
    q, s, steps = head_curve(path)
    m = steps == 1
    return float(np.interp(settlement, np.r_[0.0, s[m]], np.r_[0.0, q[m]]))


CAPACITY_SETTLEMENT = 0.015   # m: S3 capacity = head load at this settlement (all psi reach it)


def scene_values(path):
    """The stored regression values of an S2/S3 run (test/reference/s2_s3.json): head
    settlement at 1000 and 2000 kN and after unloading [mm], peak shaft sigma_n and shaft
    shear resultant at the end of loading [kPa, kN], head load at 15 mm settlement [kN]."""
    _, s, _ = head_curve(path)
    _, sig, _, q = shaft(path, last_key(path, 1))
    return {"settlement_1000": settlement_at(path, 1000.0) * 1e3,
            "settlement_2000": settlement_at(path, 2000.0) * 1e3,
            "permanent_settlement": float(s[-1]) * 1e3,
            "peak_sigma_n": float(sig[:, 0].max()),
            "shaft_resultant": abs(q),
            "capacity_15mm": load_at(path, CAPACITY_SETTLEMENT)}
