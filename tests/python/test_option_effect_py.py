"""The Python module refuses or warns where the program does (tests/test_option_effect.py).

- dispersion: steps_per_sample other than its default with solver cvode or
  arkode (which choose their own steps) is refused naming it, as
  `granwave dispersion --solver cvode --steps-per-sample 8` exits 2; with rk4
  it acts (another RK4 step, other ridge numbers).
- layer_stats: fit, gamma_deg and delta_rm given on a table whose diagram has
  no B.31 fit (every cell bounces: no boundary crossing) change nothing and
  each gives a GranwaveWarning naming it, as the program's stderr warning; on
  a table with a fit they act and say nothing.
"""
import subprocess
import warnings

import pytest

granwave = pytest.importorskip("granwave")

COLS = ("x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,"
        "block_loss_first_contact,energy_error,wave_speed,t_end,steps")


def table(path, crossing):
    """A diagram of 6 R_b/R_m x 5 H cells of 4 points: bouncing below H = 3 + 2 R_b/R_m when crossing,
    everywhere otherwise."""
    lines = ["# param vi = 20", "case,rb-rm,height-rm,point," + COLS]
    k = 0
    for x in (0.5, 1, 1.5, 2, 3, 4):
        for h in (3, 6, 9, 12, 15):
            for pt in range(4):
                b = 1 if (not crossing or h < 3 + 2 * x + 0.3 * pt or pt == 3) else 0
                lines.append("%d,%g,%g,%d,%g,%d,0.5,0.6,10,20,10,12,0.6,%g,0.001,0.6,1e-6,nan,0.01,100"
                             % (k, x, h, pt, 0.05 * pt, b, 1.5 + 0.1 * pt))
                k += 1
    path.write_text("\n".join(lines) + "\n")
    return path


def test_dispersion_steps_per_sample_refused_with_adaptive_solvers(program):
    for solver in ("cvode", "arkode"):
        with pytest.raises(granwave.GranwaveValueError, match=r"steps_per_sample: has no effect with the %s" % solver):
            granwave.dispersion(n=32, t_samples=128, solver=solver, steps_per_sample=8)
        p = subprocess.run([program, "dispersion", "--n", "32", "--t-samples", "128", "--solver", solver,
                            "--steps-per-sample", "8", "--json"], capture_output=True, text=True)
        assert p.returncode == 2 and p.stdout == "" and len(p.stderr.splitlines()) == 1, p.stderr
        assert "--steps-per-sample: has no effect with the %s solver" % solver in p.stderr
    # the default's value given is refused alike (an optional row: given is told
    # from not given); rk4 takes it and its step is another
    with pytest.raises(granwave.GranwaveValueError, match=r"steps_per_sample: has no effect with the cvode"):
        granwave.dispersion(n=32, t_samples=128, solver="cvode", steps_per_sample=16)
    granwave.dispersion(n=32, t_samples=128, solver="cvode")
    a = granwave.dispersion(n=32, t_samples=128)
    b = granwave.dispersion(n=32, t_samples=128, steps_per_sample=8)
    assert b["dt_step"] == pytest.approx(2 * a["dt_step"], rel=1e-15)
    assert a["max_overlap_dev"] != b["max_overlap_dev"]


@pytest.mark.parametrize("kw,name", [({"gamma_deg": 0.5}, "gamma-deg"), ({"delta_rm": 0.5}, "delta-rm"),
                                     ({"fit": "beta,a_over_b,offset"}, "fit")])
def test_layer_stats_fit_options_without_a_fit_warn(tmp_path, program, kw, name):
    flat = table(tmp_path / "flat.csv", crossing=False)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r0 = granwave.layer_stats(str(flat))
        r = granwave.layer_stats(str(flat), **kw)
    said = [str(x.message) for x in w if issubclass(x.category, granwave.GranwaveWarning)]
    mine = [s for s in said if "no diagram has a B.31 fit" in s]
    key = name.replace("-", "_")  # Python names the keyword, the program its flag (below)
    assert len(mine) == 1 and mine[0].startswith("layer_stats: %s: has no effect" % key), said
    assert not r["diagrams"]["fit_ok"][0] and not r0["diagrams"]["fit_ok"][0]
    assert any(x.startswith("%s: has no effect" % key) for x in r["warnings"])  # recorded in the result too
    flag = "--" + name
    value = str(list(kw.values())[0])
    p = subprocess.run([program, "layer-stats", str(flat), flag, value, "--json"], capture_output=True, text=True)
    assert p.returncode == 0
    assert "granwave layer-stats: warning: %s: has no effect: no diagram has a B.31 fit" % name in p.stderr
    # with a boundary the option acts (the fit differs) and nothing is said of it
    cross = table(tmp_path / "cross.csv", crossing=True)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        d0 = granwave.layer_stats(str(cross))["diagrams"]
        d1 = granwave.layer_stats(str(cross), **kw)["diagrams"]
    assert not [x for x in w if "no diagram has a B.31 fit" in str(x.message)]
    assert d0["fit_ok"][0] and d1["fit_ok"][0]
    fit = ("offset", "beta", "a_over_b", "tan_gamma", "rms_residual")
    assert [d0[k][0] for k in fit] != [d1[k][0] for k in fit]


def flat_table(path):
    """4 cases over rb-rm alone: no bouncing diagram (it needs rb-rm and height-rm)."""
    lines = ["# param vi = 20", "case,rb-rm,point," + COLS]
    for k in range(4):
        lines.append("%d,%g,%d,0,%d,0.5,0.6,10,20,10,12,0.6,1.5,0.001,0.6,1e-6,nan,0.01,100"
                     % (k, 1 + (k // 2) * 0.5, k % 2, k % 2))
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("fit", ["beta,a_over_b", "a_over_b,beta"])
def test_layer_stats_fit_at_its_default_is_given(tmp_path, program, fit):
    """fit is an optional row: the default's list given (in any order) is told
    from none, in Python and the program alike. Before, it was judged by its
    text: "beta,a_over_b" ran silently where "a_over_b,beta" was refused (no
    diagram) or warned of as "beta,a_over_b,offset" is (no fit)."""
    nodia = flat_table(tmp_path / "nodia.csv")
    with pytest.raises(granwave.GranwaveValueError, match=r"layer_stats: fit: has no effect: the table has no bouncing"):
        granwave.layer_stats(str(nodia), fit=fit)
    p = subprocess.run([program, "layer-stats", str(nodia), "--fit", fit, "--json"], capture_output=True, text=True)
    assert p.returncode == 2 and p.stdout == "" and len(p.stderr.splitlines()) == 1, p.stderr
    assert p.stderr.startswith("granwave layer-stats --fit: has no effect: the table has no bouncing"), p.stderr
    # not given: both run
    granwave.layer_stats(str(nodia))
    assert subprocess.run([program, "layer-stats", str(nodia), "--json"], capture_output=True).returncode == 0
    # a diagram without a boundary crossing: warned of, in both, given or not as the library says
    flat = table(tmp_path / "flat.csv", crossing=False)
    for kw, args, said in (({"fit": fit}, ["--fit", fit], True), ({}, [], False)):
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            r = granwave.layer_stats(str(flat), **kw)
        mine = [str(x.message) for x in w if "no diagram has a B.31 fit" in str(x.message)]
        assert (mine == ["layer_stats: fit: has no effect: no diagram has a B.31 fit (no R_b/R_m column changes "
                         "from bouncing to not along H: no boundary crossing to fit)"]) == said, mine
        assert any(x.startswith("fit: has no effect") for x in r["warnings"]) == said
        p = subprocess.run([program, "layer-stats", str(flat), "--json"] + args, capture_output=True, text=True)
        assert p.returncode == 0
        assert ("granwave layer-stats: warning: fit: has no effect: no diagram has a B.31 fit" in p.stderr) == said
