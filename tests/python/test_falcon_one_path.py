"""granwave.falcon and `granwave falcon` are one path (granwave issue #18): the
program runs the library's gw_chain_falcon_run, as Python does, so for the same
inputs every number of its --json and of its --out tables equals Python's
result exactly: the per-velocity numbers of the JSON, each collision's row of
falcon_runs.csv and each bead's row of falcon_final_velocities.csv (read back at
the precision the file prints: Python's value printed the same way). Before,
the program ran its own loop and differed for dt_out=0 (it sampled every
tau_1/200, the library tau_1/10 by the accuracy target), and Python had no
per-bead final velocities at all. tests/test_falcon_one_path.c holds the C
side (the library's outcome against the files, byte for byte, traces too)."""
import csv
import json
import math
import subprocess

import numpy as np
import pytest

import granwave

SETS = [
    # (the program's flags, Python's keywords)
    (["--n", "1:8", "--heights", "none", "--dt-out", "0"], dict(n=(1, 8), heights=[], dt_out=0)),
    (["--n", "5:12", "--vimp", "0.2,0.45", "--heights", "3.1"], dict(n=(5, 12), vimp=[0.2, 0.45], heights=[3.1])),
    (["--n", "1:6", "--heights", "none", "--solver", "cvode"], dict(n=(1, 6), heights=[], solver="cvode")),
    (["--n", "2:7", "--heights", "none", "--damping", "hc", "--restitution", "0.9"],
     dict(n=(2, 7), heights=[], damping="hc", restitution=0.9)),
]


def _same(a, b):
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


def _printed(x, fmt):
    """x as the program prints it with fmt, read back."""
    return float(fmt % x)


def _rows(path):
    with open(path) as fp:
        lines = [ln for ln in fp if not ln.startswith("#")]
    return list(csv.DictReader(lines))


@pytest.mark.parametrize("flags,kw", SETS, ids=[" ".join(s[0]) for s in SETS])
def test_program_equals_python(program, tmp_path, flags, kw):
    out = tmp_path / "out"
    p = subprocess.run([program, "falcon", *flags, "--out", str(out), "--json", "--quiet", "--jobs", "2"],
                       capture_output=True, text=True, check=True)
    cli = json.loads(p.stdout)
    f = granwave.falcon(jobs=2, **kw)
    nv, nn = f.nv, f.nn
    # the JSON's per-velocity numbers: Python's arrays of the same names, exactly
    keys = [k for k, v in f.items() if isinstance(v, np.ndarray) and v.shape == (nv,)]
    assert len(keys) >= 21
    for iv, vel in enumerate(cli["velocities"]):
        for k in keys:
            got = vel[k] if vel[k] is not None else math.nan
            assert _same(got, float(f[k][iv])), (k, iv, got, f[k][iv])
    assert cli["unfinished"] == f.unfinished and cli.get("accuracy_target", 0) == f.accuracy
    # each collision's row of falcon_runs.csv
    runs = _rows(out / "falcon_runs.csv")
    assert len(runs) == nv * nn
    cols = [("f_max_N", "f_max", "%.12g"), ("tau_max_s", "tau_max", "%.12g"), ("tau_n_s", "tau_n", "%.12g"),
            ("period_s", "period", "%.12g"), ("e_rel_over_e_k", "e_rel_over_e_k", "%.12g"),
            ("eps_eff", "eps_eff", "%.12g"), ("eps_col", "eps_col", "%.12g"),
            ("energy_error", "energy_error", "%.4g"), ("t_max_s", "t_max", "%.17g"),
            ("dt_out_s", "dt_out", "%.17g"), ("dt_s", "dt", "%.17g"), ("dt_max_s", "dt_max", "%.17g")]
    ints = [("n_maxima", "n_maxima"), ("n_s", "n_s"), ("cluster", "cluster"), ("steps", "steps"),
            ("rhs_evals", "rhs_evals")]
    for i, row in enumerate(runs):
        iv, k = divmod(i, nn)
        assert float(row["v_imp_m_s"]) == _printed(f.v_imp[iv], "%.10g") and int(row["n"]) == f.n[k]
        for c, key, fmt in cols:
            assert _same(float(row[c]), _printed(f[key][iv][k], fmt)), (c, iv, k)
        for c, key in ints:
            assert int(row[c]) == f[key][iv][k], (c, iv, k)
    # each bead's row of falcon_final_velocities.csv: Python's bead table
    beads = _rows(out / "falcon_final_velocities.csv")
    assert f.nbeads == len(beads) == nv * sum(range(int(f.n[0]), int(f.n[-1]) + 1))
    for i, row in enumerate(beads):
        assert float(row["v_imp_m_s"]) == _printed(f.bead_v_imp[i], "%.10g")
        assert int(row["n"]) == f.bead_n[i] and int(row["bead"]) == f.bead[i]
        for c, key in [("final_v_m_s", "final_v"), ("detach_t_s", "detach_t"), ("v_tau_n_m_s", "v_tau_n")]:
            assert float(row[c]) == _printed(f[key][i], "%.12g"), (c, i)


def test_bead_table_is_each_collisions_beads():
    """The bead table holds every bead of every collision in order (velocity,
    N, bead) and obeys the momentum balance of each: eps_eff (F.7) is minus
    the mean final velocity over v_imp (the beads' masses equal)."""
    f = granwave.falcon(n=(1, 6), vimp=[0.3, 0.5], heights=[], jobs=2)
    row = 0
    for iv in range(f.nv):
        for k, n in enumerate(f.n.astype(int)):
            sl = slice(row, row + n)
            assert (f.bead_v_imp[sl] == f.v_imp[iv]).all() and (f.bead_n[sl] == n).all()
            assert (f.bead[sl] == np.arange(1, n + 1)).all()
            assert -f.final_v[sl].mean() / f.v_imp[iv] == pytest.approx(f.eps_eff[iv][k], rel=1e-9)
            row += n
    assert row == f.nbeads
