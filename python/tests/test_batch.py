"""lac.solve_batch: columns, broadcasting, against one-by-one solves and the CLI's --batch, threads,
and a Dask LocalCluster run identical to the local one (bounded: a subprocess with a timeout)."""
import json
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import lac


def g1_data(n, seed=3):
    rng = np.random.default_rng(seed)
    return {"p0": (0, 0), "p1": (1, 0), "theta0": rng.uniform(-2.5, 2.5, n), "theta1": rng.uniform(-2.5, 2.5, n),
            "alpha": -1.0}


def test_solve_batch_columns_match_single_solves():
    d = g1_data(300)
    t = lac.solve_batch("g1", d)
    for key in ("status", "message", "length", "kappa0", "kappa1", "iterations", "evaluations", "seconds", "error",
                "accept", "usable"):
        assert len(t[key]) == 300, key
    assert t.status.dtype.kind == "U"
    for i in range(0, 300, 7):
        r = lac.g1_hermite(p0=(0, 0), theta0=d["theta0"][i], p1=(1, 0), theta1=d["theta1"][i], alpha=-1.0)
        assert t.status[i] == r.status
        assert t.usable[i] == r.usable
        if r.usable:
            assert t.length[i] == r.curve.length and t.kappa0[i] == r.summary["kappa0"]
        else:
            assert np.isnan(t.length[i]) and t.message[i] == r.message
        assert t.iterations[i] == r.summary["iterations"] and t.evaluations[i] == r.summary["evaluations"]
    assert np.mean(t.usable) > 0.9


def test_solve_batch_broadcast_points_threads_and_invalid_rows():
    n = 64
    rng = np.random.default_rng(5)
    p1 = np.stack([rng.uniform(0.5, 2, n), rng.uniform(-1, 1, n)], axis=1)
    d = {"p0": np.zeros(n, dtype=complex), "p1": p1, "theta0": 0.2, "theta1": rng.uniform(-1, 1, n),
         "alpha": rng.choice([-1.0, 0.0, 0.5, 2.0], n)}
    a = lac.solve_batch("g1", d, threads=1)
    b = lac.solve_batch("g1", d, threads=4)
    for key in ("status", "length", "kappa0", "kappa1", "iterations", "evaluations"):
        np.testing.assert_array_equal(a[key], b[key])
    d["alpha"] = np.where(np.arange(n) == 3, 9.0, d["alpha"])  # one invalid row
    c = lac.solve_batch("g1", d, solver="toms748")
    assert c.status[3] == "invalid_input" and "alpha" in c.message[3] and not c.usable[3]
    assert np.sum(c.status == "invalid_input") == 1
    with pytest.raises(lac.InputError, match="theta1"):
        lac.solve_batch("g1", {"p0": (0, 0), "p1": (1, 0), "theta0": np.zeros(3), "theta1": np.zeros(4), "alpha": -1})
    with pytest.raises(lac.InputError, match="kind"):
        lac.solve_batch("g3", d)
    with pytest.raises(TypeError, match="did you mean 'winding'"):
        lac.solve_batch("g1", d, windin=1)


def test_solve_batch_g2():
    n = 5  # theta0 = 0.4, 0.5, 0.6, 0.7, 0.8
    t = lac.solve_batch("g2", {"p0": (0, 0), "p1": (4, 0), "theta0": np.linspace(0.4, 0.8, n), "kappa0": 0.5,
                               "theta1": -0.6, "kappa1": -0.3, "alpha": -0.5}, solver="newton")
    assert np.all(t.usable)
    g = lac.g2_hermite(p0=(0, 0), theta0=np.linspace(0.4, 0.8, n)[2], kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3,
                       alpha=-0.5)
    assert t.length[2] == g.curve.length


def test_solve_batch_matches_cli_batch(lac_cli, tmp_path):
    d = g1_data(40, seed=11)
    csv = tmp_path / "rows.csv"
    csv.write_text("p0,theta0,p1,theta1,alpha\n" + "".join(
        f"\"0,0\",{a!r},\"1,0\",{b!r},-1\n" for a, b in zip(d["theta0"], d["theta1"])))
    out = subprocess.run([lac_cli, "g1", "--batch", str(csv)], capture_output=True, text=True, timeout=60)
    assert out.returncode in (0, 3), out.stderr
    rows = [json.loads(line) for line in out.stdout.splitlines() if line.strip()]
    t = lac.solve_batch("g1", d)
    assert len(rows) == 40
    for i, j in enumerate(rows):
        assert t.status[i] == j["status"]
        if j["length"] is not None:
            assert t.length[i] == pytest.approx(j["length"], rel=1e-15)
            assert t.kappa1[i] == pytest.approx(j["kappa1"], rel=1e-15)


DASK_SCRIPT = textwrap.dedent("""
    import numpy as np, lac
    from dask.distributed import Client, LocalCluster
    rng = np.random.default_rng(7)
    n = 500
    d = {"p0": (0, 0), "p1": (1, 0), "theta0": rng.uniform(-2, 2, n), "theta1": rng.uniform(-2, 2, n), "alpha": -1.5}
    local = lac.solve_batch("g1", d)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=PROCESSES, dashboard_address=None) as cluster, \\
            Client(cluster, timeout=30) as client:
        far = lac.solve_batch("g1", d, client=client, chunk_rows=64)
    for key in ("status", "length", "kappa0", "kappa1", "iterations", "evaluations", "error"):
        np.testing.assert_array_equal(local[key], far[key])
    assert list(local["message"]) == list(far["message"])
    print("identical", n, int(local["usable"].sum()))
""")


@pytest.mark.skipif(os.environ.get("LAC_DASK_TESTS", "1") == "0", reason="LAC_DASK_TESTS=0")
@pytest.mark.parametrize("processes", [False, True])
def test_dask_local_cluster_identical_to_local(processes):
    pytest.importorskip("distributed")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    try:
        out = subprocess.run([sys.executable, "-c", DASK_SCRIPT.replace("PROCESSES", str(processes))], env=env,
                             capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        pytest.fail("the Dask run did not finish within 120 s")
    assert out.returncode == 0, out.stderr[-3000:]
    assert "identical 500" in out.stdout


def test_triangle_and_compound_batches_match_the_drawable_experiment():
    """Cells of results/planar_drawable_grid.csv (exp_planar_drawable, grid 36) re-solved by
    solve_batch kinds triangle / compound: same status and Lambda."""
    import csv
    import math
    import pathlib

    path = pathlib.Path(__file__).resolve().parents[2] / "results" / "planar_drawable_grid.csv"
    rows = [r for r in csv.reader(line for line in open(path) if not line.startswith("#"))][1:]
    grid = 36
    picked = rows[::40]  # every panel, monotonic and compound
    a1 = []
    for r in picked:
        b0, b2 = float(r[5]), float(r[6])
        i, j = round(b0 * grid / math.pi - 0.5), round(b2 * grid / math.pi - 0.5)
        b0, b2 = (i + 0.5) * math.pi / grid, (j + 0.5) * math.pi / grid
        h = math.sin(b0) * math.sin(b2) / math.sin(b0 + b2)
        a1.append(complex(h / math.tan(b0), h))
    a1 = np.array(a1)
    mono = np.array([float(r[4]) == 1 for r in picked])
    got_status = np.empty(len(picked), dtype="<U17")
    got_lambda = np.zeros(len(picked))
    t = lac.solve_batch("triangle", {"a0": (0, 0), "a1": a1[mono], "a2": (1, 0),
                                     "alpha": np.array([float(r[2]) for r, m in zip(picked, mono) if m])})
    got_status[mono], got_lambda[mono] = t.status, np.nan_to_num(t.lambda0_user)
    c = [r for r, m in zip(picked, mono) if not m]
    t = lac.solve_batch("compound", {"a0": (0, 0), "a1": a1[~mono], "a2": (1, 0),
                                     "alpha0": np.array([float(r[2]) for r in c]),
                                     "alpha1": np.array([float(r[3]) for r in c]), "r": np.array([float(r[4]) for r in c])})
    got_status[~mono], got_lambda[~mono] = t.status, np.nan_to_num(t.lambda0_user)
    assert mono.sum() > 50 and (~mono).sum() > 50
    for r, s, lam in zip(picked, got_status, got_lambda):
        assert s == r[7], r
        assert lam == pytest.approx(float(r[8]), rel=1e-9, abs=0), r
    # and one compound row against lac.compound
    k = int(np.argmax(~mono))
    r = lac.compound([(0, 0), (a1[k].real, a1[k].imag), (1, 0)], alpha0=float(picked[k][2]),
                     alpha1=float(picked[k][3]), r=float(picked[k][4]))
    assert r.status == got_status[k]
