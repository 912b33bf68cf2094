"""The pure-Python pieces of pecplas_py.bench.amg on synthetic data (no benchmark run, no
pyamg): the check of the exported matrix's layout, the rigid-body modes, the fits and the
fragment's claims."""
from pathlib import Path

import h5py
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]

from pecplas_py.bench import amg as bench_amg


def spd_matrix(n, seed=1):
    rng = np.random.default_rng(seed)
    m = rng.standard_normal((n, n))
    a = m @ m.T + n * np.eye(n)
    a[np.abs(a) < 0.8] = 0.0  # some structural zeros, the diagonal stays
    return a


def csc_arrays(a, upper):
    """0-based CSC of the dense a (only i <= j with upper), as the bench program writes it."""
    n = a.shape[0]
    colptr, rowind, values = [0], [], []
    for j in range(n):
        for i in range(n):
            if a[i, j] != 0.0 and (not upper or i <= j):
                rowind.append(i)
                values.append(a[i, j])
        colptr.append(len(rowind))
    return np.array(colptr), np.array(rowind), np.array(values)


@pytest.mark.parametrize("upper", [False, True])
def test_csc_product_equals_the_dense_product(upper):
    # the same matrix stored whole or as its upper triangle: K u as numpy's dense product,
    # to rounding (sums of 12 terms)
    a = spd_matrix(12)
    u = np.linspace(-1.0, 2.0, 12)
    y = bench_amg.csc_product(*csc_arrays(a, upper), upper, u)
    assert np.allclose(y, a @ u, rtol=0, atol=1e-12 * np.abs(a @ u).max())


def write_tangent(path, a, upper_stored, upper_flag):
    colptr, rowind, values = csc_arrays(a, upper_stored)
    u = np.cos(np.arange(a.shape[0]))
    with h5py.File(path, "w") as f:
        f.attrs["upper"] = np.int32(upper_flag)
        f.attrs["factorisations"] = np.int32(3)
        for k, v in (("colptr", colptr), ("rowind", rowind), ("values", values), ("u_free", u),
                     ("k_u", a @ u), ("eq_node", np.arange(1, a.shape[0] + 1)),
                     ("eq_dir", np.ones(a.shape[0], int)),
                     ("coordinates", np.zeros((a.shape[0], 2)))):
            f[k] = v


def test_layout_check_accepts_the_written_layout_and_refuses_a_wrong_one(tmp_path):
    a = spd_matrix(10)
    write_tangent(tmp_path / "ok.h5", a, upper_stored=True, upper_flag=1)
    _, attrs, layout = bench_amg.read_tangent(tmp_path / "ok.h5")
    assert layout < 1e-13 and attrs["factorisations"] == 3
    # the upper triangle read as a whole matrix (the mistake the check is for): K u is then
    # off by the missing lower triangle, a sizeable part of the product
    write_tangent(tmp_path / "bad.h5", a, upper_stored=True, upper_flag=0)
    _, _, layout = bench_amg.read_tangent(tmp_path / "bad.h5")
    assert layout > 0.05


def test_rigid_body_modes_are_translations_and_the_rotation():
    # equations: point (2, 3) in x and y, point (-1, 5) in y only
    xy = np.array([[2.0, 3.0], [2.0, 3.0], [-1.0, 5.0]])
    dirn = np.array([1, 2, 2])
    b = bench_amg.rigid_body_modes(xy, dirn)
    assert b[:, 0].tolist() == [1, 0, 0]
    assert b[:, 1].tolist() == [0, 1, 1]
    # a unit rotation about the origin moves (x, y) by (-y, x)
    assert b[:, 2].tolist() == [-3.0, 2.0, -1.0]


def rows_from(its, cholmod):
    """Synthetic rows: CG iterations c N^q and CHOLMOD time per factorisation a N^p."""
    rows = []
    for soil, q, p in (("drucker_prager", its, cholmod), ("elastic", 0.0, cholmod)):
        for n in (1e4, 1e5, 1e6):
            it4 = round(10 * (n / 1e4) ** q)
            rows.append([soil, int(n), 10, 1e-8 * n**p, it4, 2 * it4, 1e-6 * n, 2e-6 * n, 0.0,
                         0.5])
    return rows


def test_exponents_recover_the_growth_of_synthetic_rows():
    e = bench_amg.exponents(rows_from(0.3, 1.4), "drucker_prager")
    # rounding the counts to integers moves the fitted slope by well under 0.02
    assert e["it4"] == pytest.approx(0.3, abs=0.02)
    assert e["cholmod"] == pytest.approx(1.4, abs=1e-9)
    assert e["amg"] == pytest.approx(1.0, abs=1e-9)
    assert bench_amg.exponents(rows_from(0.3, 1.4), "elastic")["it4"] == pytest.approx(0.0)


def test_fragment_states_the_growth_and_marks_unconverged_solves():
    rows = rows_from(0.3, 1.4)
    rows[2][5] = bench_amg.MAX_CG + 1
    text = bench_amg.fragment(rows, quick=False)
    assert "CG iterations grow as N^0.30 (1e-4)" in text
    # one solve costs N^(1 + q), stated against the factorisation's exponent
    assert "costs about N^1.30, against N^1.40" in text
    assert f"> {bench_amg.MAX_CG}" in text
    assert "- elastic: CG iterations grow as N^0.00 (1e-4)" in text


def test_fragment_verdict_follows_the_data():
    # iterations growing as N^0.3: a solve costs N^1.3 > N^1.25, the verdict says so
    text = bench_amg.fragment(rows_from(0.3, 1.4), quick=False)
    assert "are not flat" in text and "would not bring" in text
    assert "On the elastic stiffness of the same meshes they grow as N^0.00" in text
    # iterations growing as N^0.1: a solve within N^1.25, no such claim
    text = bench_amg.fragment(rows_from(0.1, 1.4), quick=False)
    assert "would not bring" not in text
    assert "costs about N^1.10, within N^1.25" in text


def test_rows_read_back_from_the_csv_give_the_same_fragment(tmp_path, monkeypatch):
    # --render rewrites the fragment from the CSV alone: the rows must come back with
    # their types (integer counts, so '> 1000' and the exponents are the same)
    rows = rows_from(0.3, 1.4)
    rows[2][5] = bench_amg.MAX_CG + 1
    monkeypatch.setattr(bench_amg, "BENCH_DIR", tmp_path)
    from pecplas_py.bench import common as bench_common
    bench_common.write_csv(tmp_path / "amg.csv", bench_amg.HEADER, rows)
    back = bench_amg.read_rows(tmp_path / "amg.csv")
    assert back == rows
    assert bench_amg.fragment(back, False) == bench_amg.fragment(rows, False)


def test_elastic_deck_turns_the_scaling_footing_elastic(tmp_path):
    # the contrast rows must really be elastic: the footing deck of the scaling bench with
    # its Drucker-Prager line made elastic (same E, nu, weight), and any other deck refused
    from pecplas_py.bench import scaling as bench_scaling
    deck = tmp_path / "footing.inp"
    bench_scaling.make_deck(8, 4, deck)
    bench_amg.elastic_deck(deck)
    text = deck.read_text()
    assert "*MATERIAL, NAME=clay, TYPE=ELASTIC\nE = 2.0e4, NU = 0.3, GAMMA = 18.0\n" in text
    assert "DRUCKER_PRAGER" not in text and "PHI" not in text
    with pytest.raises(RuntimeError):
        bench_amg.elastic_deck(deck)   # already elastic: not the deck it expects
