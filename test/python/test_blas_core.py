"""OpenBLAS's kernels (src/linalg/blas_core.f90, doc/build.md "OpenBLAS's kernels"): the
program runs itself again with OPENBLAS_CORETYPE set when OpenBLAS fell back to a generic core
on a CPU with AVX2/FMA or AVX-512; PECPLAS_BLAS_CORE=keep keeps OpenBLAS's own choice.

The deck: the strip footing of footing_decks (T6, nf = 12: 4839 equations, so that CHOLMOD
factorises supernode by supernode through the BLAS) on an associated Mohr-Coulomb soil
(c = 10 kPa, phi = psi = 30: symmetric tangent, CHOLMOD), pushed down 10 mm in 4 increments
under full Newton with TOLERANCE = 1e-8. The two runs differ only in the BLAS kernels, which
round differently. What they must agree on is what the iteration guarantees: both complete
with every increment's residual force norm within tol times the load norm (doc/deck.md,
*SOLVER). The load of this displacement-driven run is the reaction at the supports, and each
run's reactions are those of the exact equilibrium state up to its out-of-balance force, at
most tol times the load norm (to first order in it); so the two runs' reaction vectors differ
by at most 2 tol = 2e-8 of the reaction norm. Measured on an AVX-512 VM (OpenBLAS 0.3.21,
Prescott against SkylakeX kernels): 1e-12 of it, the same iteration counts.

On any CPU: the summary and the results file say which kernels ran; where OpenBLAS reports a
generic core and the CPU (/proc/cpuinfo) has AVX2 and FMA, the default run reports the kernels
the program set (SkylakeX with AVX-512 F/BW/DQ/VL, else Haswell) over OpenBLAS's core."""
import os
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
from pecplas_exe import pecplas_cmd  # noqa: E402
import footing_decks  # noqa: E402

TOL = 1e-8
OLD_CORES = {"unknown", "katmai", "coppermine", "northwood", "prescott", "banias", "atom",
             "core2", "penryn", "dunnington", "nehalem", "athlon", "opteron", "opteron(sse3)",
             "barcelona", "nano", "bobcat", "sandybridge"}


def cpu_flags():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("flags"):
                return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def run(tmp, name, **env_set):
    deck = tmp / "footing.inp"
    if not deck.exists():
        deck.write_text(footing_decks.deck(
            elem="T6", nf=12, c=10.0, phi=30.0, psi=30.0, settle=0.01, increments=4,
            solver=f"*SOLVER, METHOD=NEWTON, TOLERANCE={TOL:g}"))
    env = {k: v for k, v in os.environ.items()
           if k not in ("OPENBLAS_CORETYPE", "PECPLAS_BLAS_CORE", "PECPLAS_BLAS_CORE_FROM")}
    env.update(env_set)
    h5 = tmp / f"{name}.h5"
    r = subprocess.run([*pecplas_cmd(), str(deck), "-o", str(h5)], cwd=tmp,
                       capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stdout + r.stderr
    line = next(ln for ln in r.stdout.splitlines() if ln.startswith(" threads: "))
    with h5py.File(h5, "r") as f:
        attrs = {k: f.attrs[k] for k in ("status", "blas", "blas_core", "blas_core_source")}
        residual = f["history/residual"][()]
        reactions = [f[f"increments/{k}/reaction"][()] for k in sorted(f["increments"])]
    return line, attrs, residual, reactions


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("blas_core")
    return {"default": run(tmp, "default"), "keep": run(tmp, "keep", PECPLAS_BLAS_CORE="keep")}


def test_summary_and_results_say_which_kernels(runs):
    for line, attrs, _, _ in runs.values():
        if attrs["blas"] == "OpenBLAS":
            assert attrs["blas_core"] and attrs["blas_core_source"], attrs
            assert f"{attrs['blas_core']} kernels: {attrs['blas_core_source']}" in line, line
        else:
            assert attrs["blas_core"] == "" and " kernels: " not in line, (line, attrs)
    keep = runs["keep"][1]
    assert keep["blas_core_source"] in ("", "detected"), keep


def test_default_sets_better_kernels_where_openblas_falls_back(runs):
    keep, default = runs["keep"][1], runs["default"][1]
    flags = cpu_flags()
    core = keep["blas_core"]
    if keep["blas"] != "OpenBLAS" or core.lower() not in OLD_CORES or core.isupper() \
            or not {"avx2", "fma"} <= flags:
        # OpenBLAS knows the CPU (or the CPU has no AVX2/FMA, or OpenBLAS is built for one
        # core: capitals): the default keeps its choice
        assert default["blas_core"] == core and default["blas_core_source"] == \
            keep["blas_core_source"], (keep, default)
        return
    want = "SkylakeX" if {"avx512f", "avx512bw", "avx512dq", "avx512vl"} <= flags else "Haswell"
    assert default["blas_core"] == want, (keep, default)
    assert default["blas_core_source"] == f"OPENBLAS_CORETYPE={want} set by pecplas over {core}"


def test_keep_and_default_agree_within_the_tolerance(runs):
    (a, ra, fa), (b, rb, fb) = runs["default"][1:], runs["keep"][1:]
    assert a["status"] == b["status"] == "completed"
    assert np.all(ra <= TOL) and np.all(rb <= TOL), (ra, rb)
    assert len(fa) == len(fb) == 4
    for x, y in zip(fa, fb):
        assert np.linalg.norm(x - y) <= 2 * TOL * np.linalg.norm(y), \
            np.linalg.norm(x - y) / np.linalg.norm(y)
