"""The text outputs spell a value the JSON gives as null one way: "n/a".

Before, the same undefined value read `nan` in chain's, falcon's, dispersion's
and layer-stats' text (a period from one wall-force maximum, P below N = 10, the
spread of one value) and `-` in softwall's. Each case below has such a value (its
JSON null is asserted first, so the case cannot pass vacuously); its text must
show `n/a` where the number stands and no `nan` anywhere.
"""
import json
import math
import re
import subprocess

from test_hostile_stats import make_rows, write

import numpy as np

NAN_WORD = re.compile(r"\bnan\b", re.IGNORECASE)


def text_and_json(program, *args):
    t = subprocess.run([program, *map(str, args)], capture_output=True, text=True)
    assert t.returncode == 0, t.stderr
    j = subprocess.run([program, *map(str, args), "--json"], capture_output=True, text=True)
    assert j.returncode == 0, j.stderr
    return t.stdout, json.loads(j.stdout)


def no_nan(text):
    assert not NAN_WORD.search(text), text


def test_chain_period_from_one_maximum(program):
    text, j = text_and_json(program, "chain", "--n", 1)
    assert j["period"] is None
    no_nan(text)
    assert re.search(r"period P\s+n/a us", text), text


def test_falcon_period_below_ten_beads(program):
    text, j = text_and_json(program, "falcon", "--n", "1:3", "--quiet")
    assert all(v["period_mean"] is None for v in j["velocities"])
    no_nan(text)
    assert text.count("P n/a us") == len(j["velocities"]), text


def test_dispersion_column_of_one_bead(program):
    text, j = text_and_json(program, "dispersion", "--column-n", 1)
    assert j["inv_period"] is None
    no_nan(text)
    assert "1/P n/a Hz (rel diff n/a)" in text, text


def test_softwall_no_prediction(program):
    text, j = text_and_json(program, "softwall", "--kwall", 1e9, "--n", "1:3", "--quiet")
    assert j["n_d_predicted"] is None
    no_nan(text)
    row = [ln for ln in text.splitlines() if ln.strip().startswith("--kwall")][0]
    assert " n/a " in row and " - " not in row, row


def test_layer_stats_spread_of_one_point(program, tmp_path):
    rows = make_rows(np.random.default_rng(4), points=1)
    path = write(tmp_path / "one.csv", rows)
    text, j = text_and_json(program, "layer-stats", path)
    assert any(g["e_n"]["std"] is None and g["e_n"]["mean"] is not None for g in j["groups"])
    assert any(g["e_n"]["mean"] is None for g in j["groups"])  # a group without a rebound
    no_nan(text)
    assert "e_n n/a +- n/a" in text and re.search(r"e_n \d\.\d{3} \+- n/a", text), text
    for g in j["groups"]:
        m = g["e_n"]["mean"]
        if m is not None and not math.isnan(m):
            assert f"e_n {m:.3f} +- " in text


def test_layer_impact_undecided_rebound(program, tmp_path):
    """A block on one free disc without gravity: the bounce is decided, e_n is not
    (T_f never comes) and the text printed e_n = nan, T_i = nan ms; the first
    contact's two losses, at the block's smallest energy (1: it stops) and at the
    contact's opening (B.28, 0.64 at r = 0.5), are on its line."""
    one = tmp_path / "one.txt"
    one.write_text("granwave-layer-sample 1\nwidth 20\nrm 0.325\nvolume_ratio 1\nn 1\n10 0.325 0.325\n")
    text, j = text_and_json(program, "layer-impact", "--sample", one, "--rb-rm", 0.5, "--vi", 10, "--gravity", 0,
                            "--remove-walls", "--t-max", 0.003, "--exact")
    assert j["bounced"] is True and j["e_n"] is None and j["t_rebound"] is None
    no_nan(text)
    assert "bounced yes: e_n = n/a, e = n/a, alpha_r = n/a deg (V_nr = n/a m/s at T_i = n/a ms, T_f = n/a ms)" in text
    m = re.search(r"block loss ([0-9.e-]+) \(ends at [0-9.]+ ms\); at its opening block loss ([0-9.e-]+) \(B\.28\)", text)
    assert m and abs(float(m.group(1)) - 1) < 1e-3 and abs(float(m.group(2)) - 0.64) < 1e-3, text
