"""The thirteenth hostile pass, one run seen through every output form: the
Python module's results against the program's --json for the same case.

Yes/no results came back as ints (1, 0, and -1 for an undecided bounce) where
the JSON has true, false and null: json.dumps of a result differed from the
program's, and `r.bounced is None` never held. Every flag row of every
result table is now a bool (None: undecided), every flag array a bool array;
each test below fails on the ints.
"""
import json
import subprocess

import numpy as np
import pytest

import granwave
from granwave import _core

from conftest import run_cli

STUDIES = ("chain", "falcon", "wavespeed", "softwall", "dispersion", "drop", "layer-make", "layer-impact",
           "layer-stats")


def _flag_rows(study):
    st = _core.Study(study)
    return ([f.name for f in st.fields if f.type == _core.FLAG],
            [f.name for f in st.fields if f.type == _core.FARRAY])


def test_every_yes_no_result_is_declared_a_flag():
    """The result rows whose help reads "1: ..." (a yes/no) are flag rows, so
    that the module reads them as bools: a new row declared an int would come
    back as 0/1 again."""
    for study in STUDIES:
        st = _core.Study(study)
        for f in st.fields:
            if f.type in (_core.INT, _core.IARRAY) and f.help.startswith("1:"):
                pytest.fail(f"{study}: result {f.name} ('{f.help}') is an int, not a flag")
            if f.type in (_core.INT, _core.IARRAY) and "first collision: 1 =" in f.help:
                pytest.fail(f"{study}: result {f.name} ('{f.help}') is an int, not a flag")
    flags = {s: _flag_rows(s) for s in STUDIES}
    assert {"converged", "wall_done"} <= set(flags["chain"][0])
    assert "fitted" in flags["wavespeed"][0] and {"rigid", "saturated"} <= set(flags["softwall"][1])
    assert {"block", "impacts_monotone", "cut_first_collision", "open_at_t_max"} <= set(flags["drop"][0])
    assert {"bounced", "exact"} <= set(flags["layer-impact"][0]) and "converged" in flags["layer-make"][0]


def _same_flags(res, js, keys):
    for k in keys:
        assert type(res[k]) is bool and res[k] is js[k], (k, res[k], js[k])


def test_chain_flags_as_the_json(program):
    for kw, args in ((dict(n=7), ("--n", 7)), (dict(n=7, t_max=1.95e-4), ("--n", 7, "--t-max", 1.95e-4))):
        r = granwave.chain(**kw)
        j = run_cli(program, "chain", *args)
        _same_flags(r, j, ("converged", "wall_done"))
    assert r.converged is False and r.wall_done is True  # the cut run: both values seen


def test_wavespeed_fitted_as_the_json(program):
    for v in ([0.3], [0.1, 0.3]):
        r = granwave.wavespeed(n=(5, 8), vimp=v)
        j = run_cli(program, "wavespeed", "--n", "5:8", "--vimp", ",".join(map(str, v)), "--quiet")
        assert r.fitted is j["fitted"] and r.fitted is (len(v) > 1)


def test_softwall_flag_arrays_as_the_json(program):
    r = granwave.softwall(n=(1, 8))
    j = run_cli(program, "softwall", "--n", "1:8", "--quiet")
    assert r.saturated.dtype == bool and r.rigid.dtype == bool
    assert bool(r.saturated[0]) is j["saturated"] is False
    assert bool(r.rigid[0]) is (j["wall"] == "rigid") is False
    r = granwave.softwall(n=(1, 12))
    assert r.saturated.tolist() == [True]


def test_falcon_and_dispersion_flags(program):
    assert granwave.falcon(n=(1, 3), heights=[]).rigid is True
    assert granwave.dispersion(column_n=3).column is True
    d = granwave.dispersion(n=64, f0=10)
    j = run_cli(program, "dispersion", "--n", 64, "--f0", 10)
    # resolved was [1, 0, ...] in both (the only flag the JSON gave as ints)
    assert d.column is False and d.resolved.dtype == bool and d.resolved.tolist() == j["resolved"]
    assert all(type(x) is bool for x in j["resolved"]) and sum(j["resolved"]) == j["n_resolved"]


def test_drop_flags_as_the_json(program):
    r = granwave.drop(n=3, t_max=0.02)
    j = run_cli(program, "drop", "--n", 3, "--t-max", 0.02)
    _same_flags(r, j, ("block", "impacts_monotone", "cut_first_collision", "open_at_t_max"))
    _same_flags(r.first_collision, j["first_collision"], ("converged", "wall_done"))
    assert type(r.canceled) is bool and r.canceled is False
    assert r.impacts["located"].dtype == bool
    assert r.impacts["located"].tolist() == [i["located"] for i in j["impacts"]]


def test_layer_flags_and_undecided_bounce_as_the_json(program, sample, tmp_path):
    m = granwave.layer_make(n=60, width_rm=16, seed=3, out=str(tmp_path / "s.txt"))
    jm = json.loads(subprocess.run([program, "layer-make", "--n", "60", "--width-rm", "16", "--seed", "3", "--out",
                                    str(tmp_path / "t.txt"), "--json"], check=True, capture_output=True,
                                   text=True).stdout)
    assert m.converged is jm["converged"] is True
    r = granwave.layer_impact(sample=str(sample), vi=20)
    j = run_cli(program, "layer-impact", "--sample", sample, "--vi", 20)
    assert r.bounced is j["bounced"] and type(r.bounced) is bool and r.exact is False
    # cut before the verdict: the JSON's null, Python's None (it was -1, which is true)
    r = granwave.layer_impact(sample=str(sample), vi=20, t_max=0.001)
    j = run_cli(program, "layer-impact", "--sample", sample, "--vi", 20, "--t-max", 0.001)
    assert j["bounced"] is None and r.bounced is None and r.undecided == j["undecided"]


def test_a_result_dumps_as_the_json(program):
    """json.dumps of the Python result's scalars gives the program's JSON
    values: true/false where the flags were 1/0."""
    r = granwave.chain(n=3)
    j = run_cli(program, "chain", "--n", 3)
    for k in ("converged", "wall_done", "n_s", "cluster", "wall_contacts"):
        assert json.dumps(r[k]) == json.dumps(j[k]), k
    assert np.array_equal(r.final_velocities, np.array(j["final_velocities"]))


def test_layer_stats_flag_columns_as_the_json(program):
    """layer_stats' yes/no columns were 1.0/0.0 where the JSON has true/false."""
    table = str(__import__("pathlib").Path(__file__).resolve().parents[2] / "data/measured/layer_walls/results.csv")
    r = granwave.layer_stats(table)
    j = json.loads(subprocess.run([program, "layer-stats", table, "--json"], check=True, capture_output=True,
                                  text=True).stdout)
    assert r.groups["bouncing"].dtype == bool and r.groups["verdict_certain"].dtype == bool
    assert r.groups["bouncing"].tolist() == [g["bouncing"] for g in j["groups"]]
    assert r.groups["verdict_certain"].tolist() == [g["verdict_certain"] for g in j["groups"]]
    assert r.walls["walls_bouncing"].tolist() == [w["walls"]["bouncing"] for w in j["walls"]]
    assert r.walls["walls_removed_bouncing"].tolist() == [w["walls_removed"]["bouncing"] for w in j["walls"]]
    assert False in r.groups["bouncing"].tolist() and True in r.groups["bouncing"].tolist()


@pytest.mark.parametrize("n", [1, 5])
def test_column_spectrum_has_the_json_keys(program, n):
    """dispersion(column_n=N) lacked inv_period and f_peak_rel_diff, which the
    program computed in its own code for the JSON and the text; they are the
    library's now, NaN where the JSON has null (one maximum: no period)."""
    r = granwave.dispersion(column_n=n)
    j = run_cli(program, "dispersion", "--column-n", n)
    for k in ("period", "inv_period", "f_peak", "f_peak_rel_diff", "tau_n", "n_maxima", "df", "samples"):
        assert k in r, k
        assert (j[k] is None and np.isnan(r[k])) or r[k] == j[k], (k, r[k], j[k])
    assert (n == 1) == (j["inv_period"] is None)


def test_layer_make_records_the_hash_layer_impact_reads(tmp_path):
    """layer_make(out=...) did not give the sample's hash, which the program's
    JSON has (sample_fnv1a64) and every layer-impact of it records."""
    path = tmp_path / "s.txt"
    m = granwave.layer_make(n=40, width_rm=12, seed=5, t_max=0.05, out=str(path))
    h = 0xcbf29ce484222325
    for b in path.read_bytes():
        h = ((h ^ b) * 0x100000001b3) & 0xffffffffffffffff
    assert m.sample_fnv1a64 == f"{h:016x}"
    assert granwave.layer_impact(sample=str(path), t_max=1e-4).sample_fnv1a64 == m.sample_fnv1a64
    assert granwave.layer_make(n=40, width_rm=12, seed=5, t_max=0.05).sample_fnv1a64 is None


@pytest.mark.parametrize("damping,key", [("kk", "gamma"), ("hc", "alpha")])
def test_chain_gives_the_calibrated_damping_constant(program, damping, key):
    """chain(restitution=e) ran with a damping constant calibrated from e, which
    the JSON's settings give and the Python result did not."""
    r = granwave.chain(n=2, damping=damping, restitution=0.9)
    j = run_cli(program, "chain", "--n", 2, "--damping", damping, "--restitution", 0.9)
    assert r[key] == j["settings"]["model"][key] and r[key] > 0


def test_falcon_has_every_column_of_its_runs_table(program, tmp_path):
    """falcon_runs.csv has n_maxima, cluster, steps and rhs_evals per collision
    and the JSON's settings the calibrated damping constant; granwave.falcon had
    none of them."""
    out = tmp_path / "f"
    subprocess.run([program, "falcon", "--n", "1:12", "--heights", "none", "--vimp", "0.2,0.3", "--damping", "kk",
                    "--restitution", "0.9", "--quiet", "--out", str(out)], check=True, capture_output=True)
    f = granwave.falcon(n=(1, 12), heights=[], vimp=[0.2, 0.3], damping="kk", restitution=0.9)
    rows = [line.strip().split(",") for line in open(out / "falcon_runs.csv") if not line.startswith("#")]
    head, body = rows[0], rows[1:]
    unit = ("_N", "_s", "_m_s", "_mm")
    for c in head:
        key = next((c[:-len(u)] for u in unit if c.endswith(u) and c[:-len(u)] in f), c)
        if key in ("v_imp", "h_mm", "n"):
            continue
        assert key in f, f"falcon_runs.csv column {c} is not in the Python result"
        a = np.array([float(r[head.index(c)]) for r in body]).reshape(f[key].shape)
        rtol = 1e-3 if key == "energy_error" else 1e-10  # printed with 4 digits, the others 12 to 17
        assert np.allclose(a, f[key], rtol=rtol, atol=0, equal_nan=True), c
    j = json.load(open(out / "falcon_summary.json"))
    assert f.gamma == j["settings"]["model"]["gamma"] > 0 and f.alpha == 0


def test_studies_give_the_calibrated_damping_constant(program):
    """wavespeed and softwall with restitution: the constant run, as the JSON's settings."""
    w = granwave.wavespeed(n=(5, 8), vimp=[0.2, 0.3], damping="kk", restitution=0.9)
    j = run_cli(program, "wavespeed", "--n", "5:8", "--vimp", "0.2,0.3", "--damping", "kk", "--restitution", 0.9,
                "--quiet")
    assert w.gamma == j["settings"]["model"]["gamma"] > 0 and w.alpha == 0
    s = granwave.softwall(n=(1, 6), damping="hc", restitution=0.8)
    j = run_cli(program, "softwall", "--n", "1:6", "--damping", "hc", "--restitution", 0.8, "--quiet")
    assert s.alpha == j["settings"]["model"]["alpha"] > 0 and s.gamma == 0
