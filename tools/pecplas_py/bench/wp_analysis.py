"""The pure pieces of the work-precision study (bench/work_precision.py), tested by
test/python/test_work_precision.py: Richardson extrapolation from three mesh levels with the
observed order, and the cheapest configuration within an error tolerance."""
import math


def richardson(h, f, p_range=(0.5, 8.0)):
    """Extrapolate f(h) -> h = 0 from the three finest levels (f = f0 + C h^p).

    h, f: mesh sizes and values (any order, >= 3 levels; h may have any ratios).
    Returns dict(ref, p, uncertainty, monotone, levels): the limit f0 and the observed order
    p when the three finest values converge monotonically with p inside p_range; otherwise
    (oscillating, stagnating, or p < 0.5 where the extrapolation would reach far beyond the
    data: pre-asymptotic) ref = the finest value, p = None and
    uncertainty = |f_finest - f_next| (the last change, a stated error bar, not a bound).
    With the extrapolation, uncertainty = |ref - f_finest|."""
    pts = sorted(zip(h, f), key=lambda t: -t[0])[-3:]
    if len(pts) < 3:
        raise ValueError("Richardson needs three levels")
    (h1, f1), (h2, f2), (h3, f3) = pts
    fallback = {"ref": f3, "p": None, "uncertainty": abs(f3 - f2), "monotone": False,
                "levels": (h1, h2, h3)}
    d12, d23 = f1 - f2, f2 - f3
    if d23 == 0.0 or d12 == 0.0 or d12 / d23 <= 0.0:
        return fallback
    target = d12 / d23

    def g(p):   # (h1^p - h2^p) / (h2^p - h3^p) - target, increasing in p for h1 > h2 > h3
        return (h1**p - h2**p) / (h2**p - h3**p) - target

    lo, hi = p_range
    if g(lo) > 0.0 or g(hi) < 0.0:
        return fallback
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(mid) > 0.0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    c = d23 / (h2**p - h3**p)
    ref = f3 - c * h3**p
    return {"ref": ref, "p": p, "uncertainty": abs(ref - f3), "monotone": True,
            "levels": (h1, h2, h3)}


def relative_error(value, ref):
    """|value - ref| / |ref| (nan for a failed run, value None or nan)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return float("nan")
    return abs(value - ref) / abs(ref)


def cheapest_within(rows, tol, error_key="error", cost_key="wall"):
    """The row of least cost whose error is finite and below tol (None if there is none).
    Ties in cost go to the smaller error."""
    ok = [r for r in rows
          if r.get(error_key) is not None and math.isfinite(r[error_key]) and r[error_key] < tol
          and r.get(cost_key) is not None and math.isfinite(r[cost_key])]
    return min(ok, key=lambda r: (r[cost_key], r[error_key])) if ok else None
