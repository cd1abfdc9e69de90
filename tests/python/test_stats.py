"""granwave.layer_stats against `granwave layer-stats --json` on the same table.

Both call the same library code (common/stats/), so every number agrees to the
printing of the JSON (rel 1e-12; JSON null is NaN). Two tables: a short real
sweep (model layer, 2 R_b/R_m x 2 H/R_m x 3 points on a 40-disc sample, the
sweep of tests/test_layer_stats_cli.sh) written by `granwave sweep`, and a
synthetic diagram whose rows bounce below B.31 (beta 1, a/b 4, offset 1,
gamma 0.2 deg) so that the boundary, R_crit and the fit are all defined. A bad
value raises ValueError naming the parameter; a missing table OSError."""
import json
import math
import subprocess

import numpy as np
import pytest

import granwave
from conftest import SWEEP_COLS, write_synthetic_sweep

GROUP_MOMENTS = ["e_n", "e", "alpha_r", "penetration", "penetration_rm", "block_loss_first_contact",
                 "dissipated_first_contact", "rebound_energy", "e_n_first", "e_first", "alpha_r_first"]


def cli_json(program, table, *args):
    out = subprocess.run([program, "layer-stats", str(table), *map(str, args), "--json"], check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout)


def same(a, b, what):
    b = math.nan if b is None else b
    assert a == pytest.approx(b, rel=1e-12, abs=1e-300, nan_ok=True), what


def compare(r, j):
    assert r.rows == j["rows"] and r.criterion == j["criterion"]
    assert r.ngroups == len(j["groups"]) and r.nbinary == len(j["binary"]) and r.nwalls == len(j["walls"])
    assert r.ndiagrams == len(j["diagrams"])
    G = r.groups
    for i, g in enumerate(j["groups"]):
        for k, v in g["keys"].items():
            same(G[k][i], v, f"group {i} key {k}")
        for k in ("n_points", "n_valid", "n_bounced", "bouncing", "verdict_certain", "energy_error_max",
                  "k_stable_e", "x_span", "x_span_rm", "bounce_share_decided", "bounce_share_high"):
            same(G[k][i], None if g[k] is None else float(g[k]), f"group {i} {k}")
        same(G["bounce_share"][i], g["bounce_share"], f"group {i} share")
        for m in GROUP_MOMENTS:
            same(G[m + "_mean"][i], g[m]["mean"], f"group {i} {m} mean")
            same(G[m + "_std"][i], g[m]["std"], f"group {i} {m} std")
            assert G["n_" + m][i] == g[m]["n"], f"group {i} {m} n"
        sel = r.convergence["group"] == i
        for k in ("running_mean_e_n", "running_mean_e", "running_share"):
            np.testing.assert_allclose(r.convergence[k][sel], [math.nan if v is None else v for v in g[k]],
                                       rtol=1e-12, err_msg=f"group {i} {k}")
    for i, b in enumerate(j["binary"]):
        for k in ("rb_rm", "alpha", "binary_disc", "binary_sphere"):
            same(r.binary[k][i], b[k], f"binary {i} {k}")
        same(r.binary["block_loss_first_contact_mean"][i], b["block_loss_first_contact"]["mean"], f"binary {i} mean")
        same(r.binary["block_loss_first_contact_std"][i], b["block_loss_first_contact"]["std"], f"binary {i} std")
        assert r.binary["n_block_loss_first_contact"][i] == b["block_loss_first_contact"]["n"], f"binary {i} n"
    nb = 0
    for q, d in enumerate(j["diagrams"]):
        assert r.diagrams["ok"][q] == (0 if "error" in d else 1)
        if "error" in d:
            continue
        for k in ("r_crit", "r_crit_upper", "r_min", "h_min"):
            same(r.diagrams[k][q], d[k], f"diagram {q} {k}")
        same(r.diagrams["penetration_rm_boundary"][q], d["penetration_rm_boundary"], "boundary penetration")
        for p in d["boundary"]:
            for k, c in (("rb_rm", "rb_rm"), ("h_star", "h_star"), ("h_lo", "h_lo"), ("share_lo", "share_lo"),
                         ("changes", "changes")):
                same(r.boundary[c][nb], p[k], f"diagram {q} boundary {nb} {k}")
            nb += 1
        cells = r.cells["diagram"] == q
        np.testing.assert_allclose(r.cells["share"][cells],
                                   [math.nan if v is None else v for row in d["share"] for v in row], rtol=1e-12)
        f = d["fit"]
        assert r.diagrams["fit_ok"][q] == (f is not None)
        if f is not None:
            for k in ("offset", "beta", "beta_err", "a_over_b", "a_over_b_err", "tan_gamma", "gamma_deg",
                      "corr_beta_a_over_b", "a", "b", "b_err", "x_min", "h_min_fit", "n_fit", "dof", "rms_residual",
                      "iterations"):
                same(r.diagrams[k][q], f[k], f"diagram {q} fit {k}")
    assert r.nboundary == nb


@pytest.fixture(scope="module")
def sweep_table(program, tmp_path_factory):
    """results.csv of a short layer sweep (12 impacts of 0.02 s on 40 discs)."""
    d = tmp_path_factory.mktemp("stats")
    subprocess.run([program, "layer-make", "--n", "40", "--width-rm", "14", "--seed", "2", "--out", str(d / "S.txt")],
                   check=True, capture_output=True)
    (d / "s.ini").write_text(f"[sweep]\nmodel = layer\n[grid]\nrb-rm = 0.8, 2\nheight-rm = 2, 4\npoint = 0:2\n"
                             f"[params]\nsample = {d / 'S.txt'}\npoints = 3\nt-max = 0.02\n")
    subprocess.run([program, "sweep", str(d / "s.ini"), "--out", str(d / "sw"), "--quiet", "--jobs", "2"],
                   check=True, capture_output=True)
    return d / "sw" / "results.csv"


@pytest.fixture(scope="module")
def synthetic_table(tmp_path_factory):
    """conftest's synthetic sweep: bounce iff H < B.31(R_b/R_m) (beta 1, a/b 4, offset 1, gamma 0.2 deg)."""
    return write_synthetic_sweep(tmp_path_factory.mktemp("syn") / "syn.csv")


def test_sweep_table_as_the_program(program, sweep_table):
    r = granwave.layer_stats(sweep_table)
    compare(r, cli_json(program, sweep_table))
    assert r.ngroups == 4 and r.groups["n_points"].tolist() == [3, 3, 3, 3]


def test_synthetic_diagram_as_the_program(program, synthetic_table):
    r = granwave.layer_stats(synthetic_table, criterion=0.7)
    compare(r, cli_json(program, synthetic_table, "--criterion", 0.7))
    assert r.ndiagrams == 1 and r.diagrams["fit_ok"][0] == 1 and r.diagrams["ncross"][0] >= 3
    kw = dict(fit="beta,a_over_b,offset", gamma_deg=0.3)
    r = granwave.layer_stats(input=synthetic_table, **kw)
    compare(r, cli_json(program, synthetic_table, "--fit", "beta,a_over_b,offset", "--gamma-deg", 0.3))
    # the offset fitted: delta-rm (which would hold it) has no effect, refused alike
    with pytest.raises(granwave.GranwaveValueError, match="delta_rm: has no effect when the offset is fitted"):
        granwave.layer_stats(input=synthetic_table, delta_rm=2, **kw)


def test_bad_values_name_the_parameter(synthetic_table, tmp_path):
    for kw, name in ((dict(criterion=1.5), "criterion"), (dict(criterion=0), "criterion"),
                     (dict(gamma_deg=90), "gamma_deg"), (dict(delta_rm=-1), "delta_rm"),
                     (dict(fit="beta,gamma"), "fit")):
        with pytest.raises(ValueError, match=f"^layer_stats: {name}:"):
            granwave.layer_stats(synthetic_table, **kw)
    with pytest.raises(ValueError, match="input"):
        granwave.layer_stats()
    with pytest.raises(OSError, match="missing.csv"):
        granwave.layer_stats(tmp_path / "missing.csv")
    bad = tmp_path / "bad.csv"
    bad.write_text("case,point," + SWEEP_COLS + "\n0,0,0,1,0.5,abc,10,20,10,12,0.1,0.3,0.001,0.6,1e-6,nan,0.01,100\n")
    with pytest.raises(ValueError, match="bad.csv:2: column e"):
        granwave.layer_stats(bad)
    with pytest.raises(TypeError):
        granwave.layer_stats(synthetic_table, out="x")  # --out is the program's, not the library's


@pytest.mark.parametrize("name", ["layer_diagram_8000", "layer_walls"])
def test_measured_tables_as_the_program(program, name):
    """The stored tables of the 8000-impact diagram (80 groups, the B.31 fit) and
    of the walls study (walls kept/removed pairs)."""
    from conftest import REPO
    table = REPO / "data" / "measured" / name / "results.csv"
    r = granwave.layer_stats(table)
    j = cli_json(program, table)
    compare(r, j)
    for i, w in enumerate(j["walls"]):
        for side in ("walls", "walls_removed"):
            for k, v in w[side].items():
                same(r.walls[side + "_" + k][i], None if v is None else float(v), f"walls {i} {side} {k}")
    assert r.nwalls == (6 if name == "layer_walls" else 0)
