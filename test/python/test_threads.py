"""Results do not depend on the thread count. The deck is scene S5's shear box refined 3 times
(93 GOODMAN4 joints with MODJOIN cyclic, 1395 sand elements: every element loop is long enough
to run in parallel) with the sand made Drucker-Prager (C = 10 kPa, PHI = 30, PSI = 5), the plate
moved +0.6 mm in 3 increments under full Newton (consistent tangents, UMFPACK) and +0.4 mm in
2 increments under modified Newton (elastic stiffness, CHOLMOD); each run with *SOLVER
THREADS=1 and THREADS=4 (4 threads on any machine: on fewer cores they take turns, which
changes no result).

What the program computes in parallel gives the same bits on any number of threads: each
element loop writes its own rows and points, nodal sums are serial in element order, each
column of the sparse pattern is built by one thread, and CHOLMOD's OpenMP regions run as
plain code on the calling thread (doc/deck.md, THREADS). So with the BLAS held at one thread
(PECPLAS_THREAD_PARTS=1,1,0: CHOLMOD's regions 1 thread, the BLAS 1, src/linalg/threads.f90),
THREADS=4 must give the THREADS=1 results file to the last bit: every dataset, the residual
history included; only the cpu_time column, a timing, is skipped. The results file says what
ran: element loops n, CHOLMOD's regions 1, BLAS n (or 1 when held), and the BLAS's threading.

The BLAS under CHOLMOD and UMFPACK is the one part that sums in another order on another thread
count (OpenBLAS splits its kernels by the thread count and its blocking depends on the CPU: on
an AVX-512 machine the full Newton run happened to give the same bits, with OpenBLAS's AVX2
kernels its element-mean stresses differ by 1.05e-12 of their largest value). These rounding
differences reach the fields amplified by the conditioning of the tangent, kappa_1 = 4.3e8 on
this deck (4926 equations): the normwise forward-error bound of a backward-stable solve,
kappa * n * eps = 5e-4, says nothing at the 1e-12 level, and a smaller number would be a guess.
So with the BLAS threaded the test asserts what the iteration itself decides, which rounding
does not move unless a residual lies within rounding of the
tolerance: the same status, every increment converged (its residual within the deck's
tolerance) in the same number of iterations, the same joint modes at every point (measured
with OpenBLAS's AVX2 kernels on 2 threads: the last residuals of modified Newton move by 5e-11
of themselves, 5.10254469e-5 in both runs against the tolerance 1e-4; full Newton's end at
2e-11 to 2.7e-9 against 1e-8; on 4 threads, 2 cores: modified Newton's move by 3e-8 of
themselves, 5.10254469e-5 again, full Newton's last is 3.08e-11 and 3.10e-11, and the fields
differ by up to 2.7e-11 of their largest value). The plastic branch of the update ran:
the final sand stresses differ from those of the same deck with an elastic sand by more than
1 % of their largest entry (else only the elastic predictor would have been compared)."""
import os
import re
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
from pecplas_exe import pecplas_cmd  # noqa: E402

from pecplas_py import script_cmd

ELASTIC_SAND = "*MATERIAL, NAME=sand\nE = 1e5, NU = 0.3"
DP_SAND = ("*MATERIAL, NAME=sand, TYPE=DRUCKER_PRAGER\n"
           "E = 1e5, NU = 0.3, C = 10, PHI = 30, PSI = 5")
SETTINGS = {"NEWTON": ("TOLERANCE=1e-8", 3, 0.6), "MODIFIED_NEWTON": ("TOLERANCE=1e-4", 2, 0.4)}


def make_deck(tmp, method, threads, sand=DP_SAND):
    base = tmp / "s5_r3.inp"
    if not base.exists():
        subprocess.run([*script_cmd("decks.make_s5_deck"), "--refine", "3",
                        "--cycles", "1", "-o", str(base)], check=True, cwd=ROOT,
                       capture_output=True)
    text = base.read_text()
    assert ELASTIC_SAND in text, "S5 deck layout changed: sand material not found"
    text = text.replace(ELASTIC_SAND, sand)
    tol, incs, target = SETTINGS[method]
    text, n = re.subn(r"\*STEP, NAME=load, INCREMENTS=\d+\nshear, 2.0",
                      f"*STEP, NAME=load, INCREMENTS={incs}\nshear, {target}", text)
    assert n == 1, "S5 deck layout changed: first step not found"
    text = text[:text.index("*STEP, NAME=back1")] + text[text.index("*OUTPUT"):]
    text, n = re.subn(r"\*SOLVER, METHOD=NEWTON, TOLERANCE=\S+,",
                      f"*SOLVER, METHOD={method}, {tol}, THREADS={threads},", text)
    assert n == 1, "S5 deck layout changed: *SOLVER not found"
    deck = tmp / f"threads_{method}_{threads}_{'dp' if sand == DP_SAND else 'el'}.inp"
    deck.write_text(text)
    return deck


def run(deck, threads, blas_threads=None):
    """(threads, status, {name: float array}, {name: int array}, {root attribute: value} of
    the threads of each part) of the deck's results."""
    h5 = deck.with_name(f"{deck.stem}_blas{blas_threads or threads}.h5")
    env = dict(os.environ)
    env.pop("PECPLAS_THREAD_PARTS", None)
    if blas_threads:
        env["PECPLAS_THREAD_PARTS"] = f"1,{blas_threads},0"
    r = subprocess.run([*pecplas_cmd(), str(deck), "-o", str(h5)], cwd=ROOT,
                       capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    assert f" threads: {threads} (deck;" in r.stdout, r.stdout
    return datasets(h5)


def datasets(h5):
    floats, ints = {}, {}
    with h5py.File(h5, "r") as f:
        threads = int(f.attrs["threads"])
        status = f.attrs["status"]
        parts = {k: f.attrs[k] for k in ("threads_element_loops", "threads_cholmod_regions",
                                         "threads_blas", "blas_flops_per_thread", "blas",
                                         "blas_threading")}

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
                floats[name] = obj[()]
            elif isinstance(obj, h5py.Dataset) and obj.dtype.kind in "iu":
                ints[name] = obj[()]
        f.visititems(visit)
    return threads, status, floats, ints, parts


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """{method: {'1', '4 blas1', '4', 'elastic'}: results}, each run once for the module."""
    tmp = tmp_path_factory.mktemp("threads")
    out = {}
    for method in SETTINGS:
        out[method] = {"1": run(make_deck(tmp, method, 1), 1),
                       "4 blas1": run(make_deck(tmp, method, 4), 4, blas_threads=1),
                       "4": run(make_deck(tmp, method, 4), 4),
                       "elastic": run(make_deck(tmp, method, 1, ELASTIC_SAND), 1)}
    return out


@pytest.mark.parametrize("method", list(SETTINGS))
def test_parallel_loops_give_the_same_bits(runs, method):
    """THREADS=1 against THREADS=4 with the BLAS on one thread: every dataset bit for bit."""
    (n1, s1, f1, i1, _), (n2, s2, f2, i2, _) = runs[method]["1"], runs[method]["4 blas1"]
    assert (n1, s1, n2, s2) == (1, "completed", 4, "completed")
    assert f1.keys() == f2.keys() and i1.keys() == i2.keys() and len(f1) > 5
    differ = [name for name in f1 if not name.endswith("cpu_time")
              and not np.array_equal(f1[name], f2[name], equal_nan=True)]
    differ += [name for name in i1 if not np.array_equal(i1[name], i2[name])]
    assert not differ, f"{len(differ)} datasets differ, e.g. {differ[:5]}"


@pytest.mark.parametrize("method", list(SETTINGS))
def test_threaded_blas_takes_the_same_iterations(runs, method):
    """THREADS=1 against THREADS=4 with the BLAS on four threads: what the iteration decides."""
    (n1, s1, f1, i1, _), (n2, s2, f2, i2, _) = runs[method]["1"], runs[method]["4"]
    assert (n1, s1, n2, s2) == (1, "completed", 4, "completed")
    tol = float(SETTINGS[method][0].split("=")[1])
    for f in (f1, f2):
        assert np.all(f["history/residual"] <= tol), (tol, f["history/residual"])
    assert f1.keys() == f2.keys() and i1.keys() == i2.keys()
    assert np.array_equal(i1["history/iterations"], i2["history/iterations"])
    modes = [k for k in i1 if k.startswith("increments/") and k.endswith("/mode")]
    assert modes, "no joint modes in the results"
    assert all(np.array_equal(i1[k], i2[k]) for k in modes)


@pytest.mark.parametrize("method", list(SETTINGS))
def test_results_say_what_ran(runs, method):
    """The threads of each part as the rule gives them (and as PECPLAS_THREAD_PARTS held them)."""
    for key, (loops, blas) in {"1": (1, 1), "4": (4, 4), "4 blas1": (4, 1)}.items():
        parts = runs[method][key][4]
        assert (int(parts["threads_element_loops"]), int(parts["threads_cholmod_regions"]),
                int(parts["threads_blas"]), float(parts["blas_flops_per_thread"])) \
            == (loops, 1, blas, 0.0), (key, parts)
        assert parts["blas"] in ("OpenBLAS", "BLIS", "MKL", ""), parts
        assert parts["blas_threading"] in ("pthreads", "OpenMP", "none", ""), parts


@pytest.mark.parametrize("method", list(SETTINGS))
def test_the_sand_yields(runs, method):
    a, elastic = runs[method]["1"][2], runs[method]["elastic"][2]
    last = sorted(k for k in a if k.startswith("increments/") and k.endswith("sand/stress"))[-1]
    diff = np.max(np.abs(a[last] - elastic[last]))
    assert diff > 0.01 * np.max(np.abs(elastic[last])), "sand stayed elastic"
