#!/usr/bin/env python3
"""Stability of the S1 compression-opening-closing test (input/s1/s1_open_close_kn1e5.inp)
against the joint's normal stiffness: K_n / E1 = 1, 10, ..., 1e8 (E1 = 1e5 kPa), modified Newton
alone (FALLBACK=NO, the thesis's method), modified Newton with its chain of methods and full
Newton (the default method, with its fallback), tolerance 1e-3 and 1e-4. For each run: status,
increments (and how many each method finished), iterations per increment (mean, max), total
iterations, and the largest interpenetration (closure of the zero-thickness joint, eps_n > 0, in
mm). Prints a Markdown table; with --json writes the rows to test/reference/s1_stability.json,
and --doc writes the table of doc/validation.md from that file (54 runs: 9 stiffnesses x 3
methods x 2 tolerances, about 15 minutes of one core: too slow for the tests, which rerun a few
rows against the file and check the table against it).

    python3 -m pecplas_py.scenes.s1_stability [--pecplas PATH] [--max-iterations 10000] [--json]
    python3 -m pecplas_py.scenes.s1_stability --doc [--check]
"""
import argparse
import json
import sys
import re
import subprocess
import tempfile
from pathlib import Path


from pecplas_py import ROOT
from pecplas_py.exe import exe_path
from pecplas_py.results import Results

TEMPLATE = ROOT / "input" / "s1" / "s1_open_close_kn1e5.inp"
E1 = 1e5
REFERENCE = ROOT / "test" / "reference" / "s1_stability.json"
DOC = ROOT / "doc" / "validation.md"
HEADER = ("| K_n/E1 | method | tol | status | increments (by modified / quasi- / full Newton) "
          "| iterations/increment mean (max) | total iterations | max interpenetration [mm] |"
          "\n|---|---|---|---|---|---|---|---|")
#: (METHOD, FALLBACK) of the runs: the thesis's method alone, its chain, full Newton (the default)
METHODS = (("MODIFIED_NEWTON", "NO"), ("MODIFIED_NEWTON", "YES"), ("NEWTON", "YES"))


def row(exponent, method, fallback, tol, status, it, used, pen):
    """One run as stored in the reference file."""
    return {"kn_over_e1_exp": exponent, "method": method.lower(), "fallback": fallback,
            "tol": tol, "status": str(status), "increments": int(len(it)),
            "by_method": [int((used == m).sum()) for m in (1, 2, 3)],
            "mean_iterations": round(float(it.mean()), 3), "max_iterations": int(it.max()),
            "total_iterations": int(it.sum()), "max_interpenetration_mm": float(f"{pen:.4e}")}


def render(r):
    """The Markdown line of one stored row."""
    method = r["method"] + (", no fallback" if r["fallback"] == "NO" else
                            " → chain" if r["method"] == "modified_newton" else "")
    by = " / ".join(map(str, r["by_method"]))
    return (f"| 1e{r['kn_over_e1_exp']} | {method} | {r['tol']:g} | {r['status']} | "
            f"{r['increments']} ({by}) | {r['mean_iterations']:.1f} ({r['max_iterations']}) | "
            f"{r['total_iterations']} | {r['max_interpenetration_mm']:.2e} |")


def table(rows):
    return HEADER + "\n" + "\n".join(render(r) for r in rows)


def doc_block(check):
    """Writes (or with `check` compares) the table of doc/validation.md from the reference
    file; returns the diff ('' when up to date)."""
    from pecplas_py.doc_blocks import update
    rows = json.loads(REFERENCE.read_text())["rows"]
    note = ("<!-- from test/reference/s1_stability.json (written by "
            "tools/pecplas_py/scenes/s1_stability.py "
            "--json): its runs take minutes, too slow for make test; test/python/test_docs.py "
            "reruns three rows against the file and checks its physics -->")
    return update(DOC, "scenes/s1_stability.py", {"s1-stability": note + "\n" + table(rows)}, check)


def run(exe, ratio, method, tol, maxit, tmp, fallback="YES"):
    """Runs the deck with K_n = ratio E1: status, iterations and method (1 modified, 2 quasi-,
    3 full Newton) of each increment, largest interpenetration [mm]."""
    text = TEMPLATE.read_text()
    text = re.sub(r"KN = [^,]+,", f"KN = {ratio * E1:g},", text)
    text = re.sub(r"^\*SOLVER.*$", f"*SOLVER, METHOD={method}, TOLERANCE={tol:g}, "
                  f"MAX_ITERATIONS={maxit}, MAX_CUTS=3, FALLBACK={fallback}", text, flags=re.M)
    deck = tmp / f"oc_{ratio:g}_{method}_{fallback}_{tol:g}.inp"
    deck.write_text(text)
    out = deck.with_suffix(".h5")
    subprocess.run([exe, str(deck), "-o", str(out), "--quiet"], capture_output=True, text=True)
    with Results(out) as r:
        it = r.history("iterations")
        used = r.history("method")
        pen = 0.0
        for k in r.keys:
            eps = r.field(k, "joints/joint/relative_displacement").reshape(-1, 2)
            pen = max(pen, eps[:, 0].max())
        status = r.status
    return status, it, used, pen * 1e3


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pecplas", default=None)
    ap.add_argument("--max-iterations", type=int, default=10000)
    ap.add_argument("--json", action="store_true", help=f"write the rows to {REFERENCE}")
    ap.add_argument("--doc", action="store_true", help=f"write the table of {DOC} from "
                    f"{REFERENCE} (no runs)")
    ap.add_argument("--check", action="store_true", help="with --doc: compare only")
    a = ap.parse_args()
    if a.doc:
        diff = doc_block(a.check)
        sys.stdout.write(diff)
        return 1 if diff else 0
    rows = []
    exe = a.pecplas or exe_path("pecplas")
    print(HEADER)
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        for e in range(0, 9):
            ratio = 10.0**e
            for method, fallback in METHODS:
                for tol in (1e-3, 1e-4):
                    status, it, used, pen = run(exe, ratio, method, tol, a.max_iterations, tmp,
                                                fallback)
                    rows.append(row(e, method, fallback, tol, status, it, used, pen))
                    print(render(rows[-1]), flush=True)
    if a.json:
        REFERENCE.write_text(json.dumps({
            "about": "Stability of the S1 opening-closing test against K_n / E1 (written by "
                     "tools/pecplas_py/scenes/s1_stability.py --json; the table of "
                     "doc/validation.md is "
                     "rendered from it; test/python/test_docs.py reruns a few rows and checks "
                     "the physics: interpenetration = sigma_n / K_n, full Newton completes).",
            "max_iterations": a.max_iterations, "rows": rows}, indent=1) + "\n")
        print(REFERENCE)


if __name__ == "__main__":
    sys.exit(main())
