"""One name per statistic in every form of `granwave layer-stats`.

The command gives its statistics three ways: the JSON of --json (and
boundary_fit.json), the CSV files of --out DIR, and granwave.layer_stats in
Python. A number read in one form must be found in the others under the same
name with the same value (docs/formats.md, "layer-stats outputs"). The forms
flatten the JSON by fixed rules, which this file applies on its own:

- a statistic {"mean", "std", "n"} named X is X_mean, X_std and n_X;
- the grouping keys ("keys") are columns of their own names;
- a walls side ("walls", "walls_removed") prefixes its names with side + "_";
- a diagram's fit lends its names to the diagram's row (so no name of the fit
  is one of the diagram's);
- running_* lists are the columns of convergence.csv, one row per point.

For every group, binary row, walls pair, diagram and boundary point of four
tables (three stored sweeps and a made-up one with undecided points, cut
rebounds, first contacts without a value, walls and two diagrams), the names
of each form must be the same set, and each CSV cell the JSON's value as the
CSV prints it (%.9g; null is nan, true/false 1/0); Python's values equal the
JSON's (rel 1e-12). Before this test, the JSON's block_loss_first_contact,
dissipated_first_contact, the walls sides' e_n (a mean there), walls_removed,
the fit's h_min and n_points and every statistic's n were named otherwise (or
missing) in the CSV files or in Python.
"""
import csv
import json
import math
import subprocess
import warnings

import numpy as np
import pytest

import granwave
from conftest import REPO

MOMENT = {"mean", "std", "n"}
STORED = ["layer_walls", "layer_diagram", "rebound_tf/sizes"]
KINDS = ["cross", "above", "below", "inverted"]


def is_moment(v):
    return isinstance(v, dict) and set(v) == MOMENT


def flat(obj, prefix=""):
    """A JSON object's statistics as {column: value} by the rules above (lists,
    texts and the grouping keys left out)."""
    out = {}
    for k, v in obj.items():
        if k == "keys" or isinstance(v, (list, str)):
            continue
        if is_moment(v):
            out[prefix + k + "_mean"], out[prefix + k + "_std"], out["n_" + prefix + k] = v["mean"], v["std"], v["n"]
        elif isinstance(v, dict):
            out.update(flat(v, prefix + k + "_"))
        else:
            out[prefix + k] = v
    return out


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return rows[0], [dict(zip(rows[0], r)) for r in rows[1:]]


def as_printed(v):
    """The JSON value as the CSV files print it."""
    if v is None:
        return "nan"
    if isinstance(v, bool):
        return str(int(v))
    return "%.9g" % v


def cell_is(cell, v, what):
    if isinstance(v, str):
        assert cell == v, what
    else:
        assert float(cell) == pytest.approx(float(as_printed(v)), rel=1e-15, nan_ok=True), (what, cell, v)


def py_is(a, v, what):
    b = math.nan if v is None else float(v)
    assert float(a) == pytest.approx(b, rel=1e-12, abs=1e-300, nan_ok=True), (what, a, v)


def made_up_table(path):
    """rb-rm x height-rm x remove-walls x 4 points, drawn with a fixed seed:
    undecided points, bouncing points cut before T_f, first contacts without a
    value, and a share that falls with H (two diagrams with a boundary)."""
    rng = np.random.default_rng(11)
    cols = ("x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,"
            "block_loss_first_contact,energy_error,wave_speed,t_end,steps,e_n_first,e_first,alpha_r_first")
    lines = ["# made-up layer sweep", "# param alpha = 30", "case,rb-rm,height-rm,remove-walls,point," + cols]
    case = 0
    for x in (0.5, 1, 2, 4):
        for h in (2, 6, 10, 14):
            for w in ("false", "true"):
                for p in range(4):
                    u = rng.random()
                    b = math.nan if u < 0.1 else float(u < 1.1 - h / (6 * x))
                    first = [rng.uniform(0.05, 0.4), rng.uniform(0.1, 0.5), rng.uniform(0, 60)]
                    # e_n = e cos(alpha_r) / cos(alpha_i) (B.16-B.18 with V_nr = V_r cos(alpha_r)):
                    # layer-stats refuses e_n cos(alpha_i) > e, a normal speed above the speed
                    first[0] = first[1] * math.cos(math.radians(first[2])) / math.cos(math.radians(30))
                    cut = b == 1 and rng.random() < 0.2
                    ek = [math.nan] * 3 if b != 1 or cut else first
                    if b != 1:
                        first = [math.nan] * 3
                    pen = rng.uniform(0.01, 0.2)
                    v = [0.05 * p, b, ek[0], ek[1], ek[2], 20, 3, 5, pen, pen / 0.325,
                         math.nan if rng.random() < 0.2 else rng.uniform(0, 0.3),
                         math.nan if rng.random() < 0.2 else rng.uniform(0.3, 0.9), 1e-6, math.nan, 0.05, 100,
                         *first]
                    lines.append(f"{case},{x},{h},{w},{p}," + ",".join(repr(float(q)) for q in v))
                    case += 1
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.fixture(scope="module", params=STORED + ["made_up"])
def forms(request, program, tmp_path_factory):
    """(JSON, out dir, Python result) of one table."""
    d = tmp_path_factory.mktemp("names")
    if request.param == "made_up":
        table = made_up_table(d / "t.csv")
    else:
        table = REPO / "data" / "measured" / request.param / "results.csv"
    out = subprocess.run([program, "layer-stats", str(table), "--json", "--out", str(d / "o")], check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout), d / "o", granwave.layer_stats(table)


def test_groups(forms):
    j, out, r = forms
    header, rows = read_csv(out / "groups.csv")
    keys = j["group_keys"]
    assert header[:1 + len(keys)] == ["group"] + keys
    assert list(r.group_keys) == keys
    G = r.groups
    assert len(rows) == len(j["groups"]) == r.ngroups
    for i, g in enumerate(j["groups"]):
        f = flat(g)
        assert set(f) == set(header) - {"group"} - set(keys), \
            f"group names: JSON only {sorted(set(f) - set(header))}, CSV only {sorted(set(header) - set(f) - {'group'} - set(keys))}"
        assert set(f) | set(keys) == set(G), \
            f"Python names: JSON only {sorted(set(f) - set(G))}, Python only {sorted(set(G) - set(f) - set(keys))}"
        assert rows[i]["group"] == str(i)
        for k, v in list(f.items()) + list(g["keys"].items()):
            cell_is(rows[i][k], v, f"groups.csv row {i} {k}")
            if not isinstance(v, str):
                py_is(G[k][i], v, f"Python groups {i} {k}")


def test_convergence(forms):
    j, out, r = forms
    header, rows = read_csv(out / "convergence.csv")
    C = r.convergence
    for i, g in enumerate(j["groups"]):
        mine = [row for row in rows if row["group"] == str(i)]
        sel = C["group"] == i
        for k in (k for k, v in g.items() if k.startswith("running_")):
            assert k in header and k in C, k
            assert len(mine) == len(g[k]) == int(sel.sum())
            for row, a, v in zip(mine, C[k][sel], g[k]):
                cell_is(row[k], v, f"convergence.csv group {i} {k}")
                py_is(a, v, f"Python convergence group {i} {k}")


def test_binary(forms):
    j, out, r = forms
    header, rows = read_csv(out / "binary.csv")
    assert len(rows) == len(j["binary"]) == r.nbinary
    for i, b in enumerate(j["binary"]):
        f = flat(b)
        assert set(f) == set(header) == set(r.binary), (sorted(f), header, sorted(r.binary))
        for k, v in f.items():
            cell_is(rows[i][k], v, f"binary.csv row {i} {k}")
            py_is(r.binary[k][i], v, f"Python binary {i} {k}")


def test_walls(forms):
    j, out, r = forms
    header, rows = read_csv(out / "walls.csv")
    assert len(rows) == len(j["walls"]) == r.nwalls
    for i, w in enumerate(j["walls"]):
        f = flat(w)
        keys = list(w["keys"])
        assert header == ["pair"] + keys + list(f), (header, list(f))
        assert set(f) == set(r.walls), (sorted(f), sorted(r.walls))
        for k, v in list(f.items()) + list(w["keys"].items()):
            cell_is(rows[i][k], v, f"walls.csv pair {i} {k}")
            if k in f:
                py_is(r.walls[k][i], v, f"Python walls {i} {k}")
        for side in ("walls", "walls_removed"):  # the side's group is the groups' row of its numbers
            g = j["groups"][w[side]["group"]]
            assert g["n_points"] == w[side]["n_points"] and g["bounce_share"] == w[side]["bounce_share"]


def test_diagrams(forms):
    j, out, r = forms
    header, rows = read_csv(out / "diagram.csv")
    D, B, C = r.diagrams, r.boundary, r.cells
    assert len(j["diagrams"]) == r.ndiagrams
    nb = 0
    for q, d in enumerate(j["diagrams"]):
        assert D["ok"][q] == ("error" not in d)
        if "error" in d:
            continue
        assert D["fit_ok"][q] == (d["fit"] is not None)
        f = flat({k: v for k, v in d.items() if k != "fit"})
        fit = flat(d["fit"]) if d["fit"] else {}
        assert not set(f) & set(fit), f"a name of the fit is the diagram's too: {sorted(set(f) & set(fit))}"
        for k, v in list(f.items()) + list(fit.items()):
            assert k in D, f"diagram {q}: {k} is not a column of Python's diagrams"
            py_is(D[k][q], v, f"Python diagram {q} {k}")
        cells = C["diagram"] == q
        for k in ("share", "penetration_rm"):  # the [R_b/R_m][H] matrices: Python's cells
            py = C[k][cells].tolist()
            assert len(py) == sum(len(row) for row in d[k])
            for a, v in zip(py, (v for row in d[k] for v in row)):
                py_is(a, v, f"Python cells of diagram {q} {k}")
        mine = [row for row in rows if row["diagram"] == str(q)]
        assert len(mine) == len(d["boundary"])
        for row, p in zip(mine, d["boundary"]):
            assert set(p) == set(header) - {"diagram"} - set(d["keys"]), (sorted(p), header)
            assert set(p) | {"diagram"} == set(B), (sorted(p), sorted(B))
            for k, v in p.items():
                cell_is(row[k], v, f"diagram.csv diagram {q} {k}")
                if k == "kind":
                    assert KINDS[int(B[k][nb])] == v
                else:
                    py_is(B[k][nb], v, f"Python boundary {nb} {k}")
            nb += 1
    assert nb == r.nboundary


def test_top_level(forms):
    j, out, r = forms
    for k in ("rows", "criterion"):
        assert r[k] == j[k], k
    assert list(r.group_keys) == j["group_keys"]


def test_the_names_before_read_with_a_warning(forms):
    """The tables' names before the forms agreed still read, with a warning
    naming the new one."""
    _, _, r = forms
    old = {"groups": {"n_rebound": "n_e", "n_rebound_first": "n_e_first",
                      "block_loss_mean": "block_loss_first_contact_mean",
                      "dissipated_std": "dissipated_first_contact_std"},
           "binary": {"n": "n_block_loss_first_contact", "block_loss_std": "block_loss_first_contact_std"},
           "walls": {"group_removed": "walls_removed_group", "removed_e_n_mean": "walls_removed_e_n_mean",
                     "removed_bouncing": "walls_removed_bouncing"}}
    for t, names in old.items():
        for was, now in names.items():
            assert was not in r[t]
            with pytest.warns(DeprecationWarning, match=f"'{was}' is now '{now}'"):
                a = r[t][was]
            np.testing.assert_array_equal(a, r[t][now])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(KeyError):
            r.groups["no_such_column"]
