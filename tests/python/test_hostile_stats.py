"""`granwave layer-stats` against a computation written here, on hostile tables.

Every number of --json is recomputed from the table's cells in this file
(exact rational sums for the means and deviations, numpy for the rest,
scipy.optimize.least_squares for the B.31 fit): per-group means and sample
standard deviations (n - 1), bounce shares (plain, decided, high), verdicts,
rebound energy, running means and k_stable_e, the diagram's H*, R_crit and
penetration at the boundary, and the binary-impact table. The tables are made
hostile: one point per cell, all values equal, values near the largest and the
smallest doubles, NaN cells, columns reordered, CRLF line ends, a byte-order
mark, numbers spelt two ways (2 and 2.0). Bad tables (empty, header only, a
case twice, a column missing, a grid key moved among the results, a line of
2 MB) must give exit 2 with one line naming the file, nothing written.
"""
import json
import math
import subprocess
from fractions import Fraction

import numpy as np
import pytest

scipy_optimize = pytest.importorskip("scipy.optimize")

COLS = ["x_impact", "bounced", "e_n", "e", "alpha_r", "penetration", "penetration_rm",
        "block_loss_first_contact", "dissipated_first_contact"]
GRID = ["rb-rm", "height-rm", "point"]
S = 0.75


def run(program, path, *args, check=True):
    p = subprocess.run([program, "layer-stats", str(path), "--json", *map(str, args)], capture_output=True,
                       text=True)
    if check:
        assert p.returncode == 0, p.stderr
        return json.loads(p.stdout)
    return p


def write(path, rows, cols=COLS, grid=GRID, comments=(), eol="\n", bom=False, spell=None):
    """rows: dicts with 'case', the grid keys and the columns (floats; nan)."""
    spell = spell or {}
    lines = list(comments) + [",".join(["case"] + grid + cols)]
    for r in rows:
        cells = [str(r["case"])] + [spell.get((r["case"], k), repr(float(r[k])) if k != "point" else str(r[k]))
                                    for k in grid]
        cells += ["nan" if math.isnan(r[c]) else repr(float(r[c])) for c in cols]
        lines.append(",".join(cells))
    data = (eol.join(lines) + eol).encode()
    path.write_bytes((b"\xef\xbb\xbf" if bom else b"") + data)
    return path


def make_rows(rng, xs=(0.5, 1.0, 2.0), hs=(2.0, 4.0, 8.0), points=5, scale=1.0, nan_share=0.0):
    rows, case = [], 0
    for x in xs:
        for h in hs:
            for p in range(points):
                b = float(rng.random() < 1.2 - 0.1 * h / x)
                if rng.random() < nan_share:
                    b = math.nan  # undecided
                e = rng.uniform(0.1, 0.9) * scale
                r = {"case": case, "rb-rm": x, "height-rm": h, "point": p, "x_impact": 0.05 * p * scale,
                     "bounced": b, "e_n": e * rng.uniform(0.2, 1) if b == 1 else math.nan,
                     "e": e if b == 1 else math.nan, "alpha_r": rng.uniform(0, 80) if b == 1 else math.nan,
                     "penetration": rng.uniform(0.001, 0.1) * scale, "block_loss_first_contact": rng.uniform(0, 1),
                     "dissipated_first_contact": rng.uniform(0, 1) if rng.random() > nan_share else math.nan}
                r["penetration_rm"] = r["penetration"] / 0.0325
                rows.append(r)
                case += 1
    return rows


# ------------------------------------------------------------ the reference ---

def moment(vals):
    v = [Fraction(x) for x in vals if math.isfinite(x)]
    n = len(v)
    if n == 0:
        return None, None, 0
    mean = sum(v) / n
    if n < 2:
        return float(mean), None, n
    var = sum((a - mean) ** 2 for a in v) / (n - 1)
    big = max(abs(a) for a in v)
    return float(mean), float(big) * math.sqrt(float(var / big ** 2)) if big else 0.0, n


def reference(rows, criterion=S):
    groups = {}
    for r in rows:
        groups.setdefault((float(r["rb-rm"]), float(r["height-rm"])), []).append(r)
    out = {}
    for key, g in groups.items():
        g = sorted(g, key=lambda r: (r["point"], r["case"]))
        n = len(g)
        b = np.array([r["bounced"] for r in g])
        nb, nv = int(np.sum(b == 1)), int(np.sum(~np.isnan(b)))
        bounced = [r for r in g if r["bounced"] == 1]
        o = {"n_points": n, "n_valid": nv, "n_bounced": nb, "bounce_share": nb / n,
             "bounce_share_decided": nb / nv if nv else None, "bounce_share_high": (nb + n - nv) / n,
             "bouncing": nb / n >= criterion, "verdict_certain": nb / n >= criterion or (nb + n - nv) / n < criterion}
        for c in ("e_n", "e", "alpha_r"):
            o[c] = moment([r[c] for r in bounced])
        for c in ("penetration", "penetration_rm", "block_loss_first_contact", "dissipated_first_contact"):
            o[c] = moment([r[c] for r in g])
        o["rebound_energy"] = moment([r["e"] ** 2 if r["bounced"] == 1 else 0.0 for r in g
                                      if not math.isnan(r["bounced"])])
        run_e = []
        for k in range(1, n + 1):
            m = moment([r["e"] for r in g[:k] if r["bounced"] == 1])[0]
            run_e.append(m)
        o["running_mean_e"] = run_e
        o["running_share"] = [sum(r["bounced"] == 1 for r in g[:k]) / k for k in range(1, n + 1)]
        fin = run_e[-1]
        ks = 0
        if fin is not None and fin != 0:
            ks = n
            while ks > 1 and run_e[ks - 2] is not None and abs(run_e[ks - 2] - fin) <= 0.05 * abs(fin):
                ks -= 1
        o["k_stable_e"] = ks
        out[key] = o
    return out


def ref_diagram(ref, criterion=S):
    xs = sorted({k[0] for k in ref})
    hs = sorted({k[1] for k in ref if k[1] > 0})
    bnd, r_crit = {}, None
    all_above = True
    for x in xs:
        col = [(h, ref[(x, h)]["bounce_share"], ref[(x, h)]["penetration_rm"][0]) for h in hs if (x, h) in ref]
        cross = None
        for (h0, s0, p0), (h1, s1, p1) in zip(col, col[1:]):
            if s0 >= criterion and s1 < criterion:
                cross = (h0 + (s0 - criterion) / (s0 - s1) * (h1 - h0), p0 / 2 + p1 / 2)
                break
        bnd[x] = cross
        if all_above and all(s >= criterion for _, s, _ in col):
            r_crit = x
        else:
            all_above = False
    return bnd, r_crit


def close(a, b, what, rel=1e-12):
    if b is None or (isinstance(b, float) and math.isnan(b)):
        assert a is None, f"{what}: {a} where the reference has none"
        return
    assert a is not None, f"{what}: null where the reference has {b}"
    assert a == pytest.approx(b, rel=rel, abs=1e-322), what


def check(j, rows, criterion=S):
    ref = reference(rows, criterion)
    assert j["rows"] == len(rows)
    assert len(j["groups"]) == len(ref), "groups"
    for g in j["groups"]:
        key = (float(g["keys"]["rb-rm"]), float(g["keys"]["height-rm"]))
        o = ref[key]
        for k in ("n_points", "n_valid", "n_bounced", "bouncing", "verdict_certain", "k_stable_e"):
            assert g[k] == o[k], f"{key} {k}: {g[k]} != {o[k]}"
        for k in ("bounce_share", "bounce_share_decided", "bounce_share_high"):
            close(g[k], o[k], f"{key} {k}")
        for c in ("e_n", "e", "alpha_r", "penetration", "penetration_rm", "block_loss_first_contact",
                  "dissipated_first_contact", "rebound_energy"):
            mean, std, n = o[c]
            assert g[c]["n"] == n, f"{key} {c} n"
            close(g[c]["mean"], mean, f"{key} {c} mean")
            close(g[c]["std"], std, f"{key} {c} std")
        for a, b in zip(g["running_mean_e"], o["running_mean_e"]):
            close(a, b, f"{key} running mean e")
        for a, b in zip(g["running_share"], o["running_share"]):
            close(a, b, f"{key} running share")
    bnd, r_crit = ref_diagram(ref, criterion)
    if len({k[0] for k in ref}) >= 2 and len({k[1] for k in ref}) >= 2:
        d = j["diagrams"][0]
        close(d["r_crit"], r_crit, "r_crit")
        for p in d["boundary"]:
            want = bnd[float(p["rb_rm"])]
            if want is None:
                assert p["kind"] != "cross", p
            else:
                assert p["kind"] == "cross"
                close(p["h_star"], want[0], f"H* at {p['rb_rm']}")
                close(p["penetration_rm"], want[1], f"penetration at the boundary {p['rb_rm']}")
    for b in j["binary"]:
        sel = [r["block_loss_first_contact"] for r in rows if float(r["rb-rm"]) == b["rb_rm"]]
        mean, std, n = moment(sel)
        close(b["block_loss_first_contact"]["mean"], mean, "binary mean")
        close(b["block_loss_first_contact"]["std"], std, "binary std")
        m2, m3 = b["rb_rm"] ** 2, b["rb_rm"] ** 3
        # the block stops inside a binary contact when it is no heavier (m <= 1): loss 1
        close(b["binary_disc"], 4 * m2 / (1 + m2) ** 2 if m2 > 1 else 1.0, "binary disc")
        close(b["binary_sphere"], 4 * m3 / (1 + m3) ** 2 if m3 > 1 else 1.0, "binary sphere")


# ------------------------------------------------------------------- tests ---

@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_tables_as_computed_here(program, tmp_path, seed):
    rows = make_rows(np.random.default_rng(seed), nan_share=0.1 if seed == 3 else 0.0)
    check(run(program, write(tmp_path / "t.csv", rows)), rows)
    check(run(program, tmp_path / "t.csv", "--criterion", 0.5), rows, 0.5)


def test_one_point_per_cell_and_all_values_equal(program, tmp_path):
    rows = make_rows(np.random.default_rng(4), points=1)
    j = run(program, write(tmp_path / "one.csv", rows))
    check(j, rows)
    assert all(g["e"]["std"] is None for g in j["groups"])
    rows = make_rows(np.random.default_rng(5), points=6)
    for r in rows:
        # e_n scaled with e: layer-stats refuses e_n above e at normal incidence (V_nr > V_r)
        r.update(e_n=r["e_n"] / r["e"] * 0.3 if r["bounced"] == 1 else math.nan,
                 e=0.3 if r["bounced"] == 1 else math.nan, penetration=0.1, penetration_rm=0.1 / 0.0325)
    j = run(program, write(tmp_path / "eq.csv", rows))
    check(j, rows)
    assert all(g["penetration"]["std"] == 0 for g in j["groups"])


@pytest.mark.parametrize("scale", [1e300, 1e-300, 1e-318])
def test_values_near_the_ends_of_the_doubles(program, tmp_path, scale):
    """Penetrations near 1e308 summed to inf (mean printed null); deviations
    below 1e-154 squared to 0 (std 0 for two different subnormals)."""
    rows = make_rows(np.random.default_rng(6), points=4)
    for r in rows:
        r["penetration"] = r["penetration"] * scale * 40  # up to 4e301 ... and subnormals
        r["penetration_rm"] = r["penetration"] * 3
    if scale > 1:
        for r in rows:
            r["penetration_rm"] = 1.7e308 - r["point"] * 1e307
    j = run(program, write(tmp_path / "big.csv", rows))
    check(j, rows)
    for g in j["groups"]:
        assert g["penetration"]["mean"] is not None and g["penetration"]["std"] > 0


def test_the_same_numbers_however_the_file_is_written(program, tmp_path):
    rows = make_rows(np.random.default_rng(7))
    base = run(program, write(tmp_path / "a.csv", rows))
    check(base, rows)
    cols = COLS[:1] + COLS[1:][::-1]  # model columns in another order: read by name
    variants = {"crlf": dict(eol="\r\n"), "bom": dict(bom=True), "cols": dict(cols=cols),
                "bom_crlf_comment": dict(bom=True, eol="\r\n", comments=["# a table made by hand"])}
    for name, kw in variants.items():
        j = run(program, write(tmp_path / f"{name}.csv", rows, **kw))
        assert j["groups"] == base["groups"] and j["diagrams"] == base["diagrams"] and \
            j["binary"] == base["binary"], name


def test_one_value_spelt_two_ways_is_one_group(program, tmp_path):
    """2 and 2.0 (or 2e0) of one R_b/R_m made two groups of one point each,
    with the same keys, and a diagram refused as 'another grid key varies'."""
    rows = make_rows(np.random.default_rng(8), points=3)
    spell = {(r["case"], "rb-rm"): "2e0" for r in rows if r["rb-rm"] == 2.0 and r["point"] == 1}
    spell.update({(r["case"], "height-rm"): "8" for r in rows if r["height-rm"] == 8.0 and r["point"] == 2})
    j = run(program, write(tmp_path / "s.csv", rows, spell=spell))
    check(j, rows)
    assert "error" not in j["diagrams"][0]


def test_b31_fit_as_least_squares_here(program, tmp_path):
    T = math.tan(math.radians(0.2))

    def b31(x, off, beta, ab):
        u = x - beta
        return off + (np.sqrt(u * u + ab * T * x * x) - u) / (2 * T)

    rows, case = [], 0
    for x in (0.5, 1.5, 2, 3, 4, 6):
        for h in (3, 6, 9, 12, 15, 18, 21):
            for p in range(4):
                b = 1.0 if h < b31(x, 1.0, 1.0, 4.0) + (0.3 if p == 0 else 0) else 0.0
                rows.append({"case": case, "rb-rm": x, "height-rm": h, "point": p, "x_impact": 0.05 * p,
                             "bounced": b, "e_n": 0.3 if b else math.nan, "e": 0.3 + 0.01 * p if b else math.nan,
                             "alpha_r": 10.0 if b else math.nan, "penetration": 0.01,
                             "penetration_rm": 0.4 + 0.01 * h, "block_loss_first_contact": 0.5,
                             "dissipated_first_contact": 0.1})
                case += 1
    j = run(program, write(tmp_path / "syn.csv", rows))
    check(j, rows)
    d = j["diagrams"][0]
    fit = d["fit"]
    pts = [(p["rb_rm"], p["h_star"]) for p in d["boundary"] if p["kind"] == "cross"]
    x, h = np.array(pts).T
    off = d["penetration_rm_boundary"] / 2
    assert fit["offset"] == pytest.approx(off, rel=1e-12)
    best = None
    for b0 in (0.25, 0.5, 1.0, 1.5):
        r = scipy_optimize.least_squares(lambda q: b31(x, off, q[0], math.exp(q[1])) - h, [b0, math.log(4)],
                                         xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if best is None or r.cost < best.cost:
            best = r
    assert fit["beta"] == pytest.approx(best.x[0], rel=1e-5)
    assert fit["a_over_b"] == pytest.approx(math.exp(best.x[1]), rel=1e-5)
    assert fit["rms_residual"] == pytest.approx(math.sqrt(2 * best.cost / len(x)), rel=1e-6)
    J = best.jac
    cov = np.linalg.inv(J.T @ J) * (2 * best.cost / (len(x) - 2))
    assert fit["beta_err"] == pytest.approx(math.sqrt(cov[0, 0]), rel=1e-3)
    assert fit["a_over_b_err"] == pytest.approx(fit["a_over_b"] * math.sqrt(cov[1, 1]), rel=1e-3)


def test_a_fit_over_penetrations_near_1e308_fails_without_abort(program, tmp_path):
    """GSL's default handler aborted (SIGABRT) in the B.31 fit's QR when the
    offset was near 1e300; the fit now reports why it failed."""
    rows = make_rows(np.random.default_rng(9), points=4)
    for r in rows:
        r["penetration_rm"] = 1e300
    j = run(program, write(tmp_path / "h.csv", rows))
    check(j, rows)
    d = j["diagrams"][0]
    assert d["fit"] is None and d["fit_reason"]


def refused(program, path, tmp_path, line=None):
    out = tmp_path / "out"
    p = subprocess.run([program, "layer-stats", str(path), "--out", str(out)], capture_output=True, text=True)
    assert p.returncode == 2, (p.returncode, p.stderr)
    assert p.stdout == "" and p.stderr.count("\n") == 1 and str(path) in p.stderr, p.stderr
    if line is not None:
        assert f"{path}:{line}:" in p.stderr, p.stderr
    assert not out.exists()
    return p.stderr


def test_bad_tables_exit_2_naming_the_file(program, tmp_path):
    rows = make_rows(np.random.default_rng(10), points=2)
    good = write(tmp_path / "good.csv", rows).read_text()
    hdr = good.splitlines()[0]
    (tmp_path / "empty.csv").write_text("")
    refused(program, tmp_path / "empty.csv", tmp_path)
    (tmp_path / "hdr.csv").write_text(hdr + "\n")
    refused(program, tmp_path / "hdr.csv", tmp_path, 1)
    (tmp_path / "bomhdr.csv").write_bytes(b"\xef\xbb\xbf" + hdr.encode() + b"\r\n")
    refused(program, tmp_path / "bomhdr.csv", tmp_path, 1)
    lines = good.splitlines()
    (tmp_path / "dup.csv").write_text("\n".join(lines + [lines[3]]) + "\n")
    assert "case 2" in refused(program, tmp_path / "dup.csv", tmp_path)
    miss = [",".join(c for i, c in enumerate(l.split(",")) if i != 7) for l in lines]  # e_n gone
    (tmp_path / "miss.csv").write_text("\n".join(miss) + "\n")
    refused(program, tmp_path / "miss.csv", tmp_path, 1)
    # a grid key moved among the results: R_b/R_m was read as the default 1
    moved = write(tmp_path / "moved.csv", [dict(r, **{"height-rm": 1000 * r["height-rm"] + r["case"]}) for r in rows],
                  grid=["height-rm", "point"], cols=COLS[:1] + ["rb-rm"] + COLS[1:])
    assert "rb-rm" in refused(program, moved, tmp_path, 1)
    # a 2 MB line: a comment (read) and a cell (refused naming its line)
    (tmp_path / "longc.csv").write_text("#" + "x" * (2 << 20) + "\n" + good)
    check(run(program, tmp_path / "longc.csv"), rows)
    bad = lines[:2] + [lines[2].replace(",", "," + "9" * (2 << 20), 1)] + lines[3:]
    (tmp_path / "longl.csv").write_text("\n".join(bad) + "\n")
    refused(program, tmp_path / "longl.csv", tmp_path, 3)
    for cell in ("inf", "-inf", "1e999"):
        t = lines[:2] + [lines[2].rsplit(",", 1)[0] + "," + cell] + lines[3:]
        (tmp_path / "inf.csv").write_text("\n".join(t) + "\n")
        refused(program, tmp_path / "inf.csv", tmp_path, 3)


def test_settings_outside_what_a_sweep_runs(program, tmp_path):
    """R_b/R_m <= 0, H/R_m < 0, an incidence outside [0, 90), V_i or density <= 0,
    a point < 0, as a grid value or a "# param" line, is a table no sweep wrote:
    R_b/R_m 0 and -2 gave a diagram with R_crit -2 and a binary row of mass
    ratio 0 (exit 0). Refused naming the file, the line and the setting."""
    rows = make_rows(np.random.default_rng(11), points=2)
    for key, bad in (("rb-rm", 0.0), ("rb-rm", -2.0), ("height-rm", -4.0), ("point", -1)):
        t = [dict(r) for r in rows]
        t[1][key] = bad
        msg = refused(program, write(tmp_path / "dom.csv", t), tmp_path, 3)
        assert key in msg and "is not a value a sweep runs" in msg, msg
    for name, bad in (("alpha", "90"), ("alpha", "-1"), ("vi", "0"), ("density", "-2650"), ("rb-rm", "0")):
        p = write(tmp_path / "param.csv", rows, comments=[f"# param {name} = {bad}"],
                  grid=[g for g in GRID if g != name], cols=COLS)
        msg = refused(program, p, tmp_path, 1)
        assert f"param {name}" in msg and "is not a value a sweep runs" in msg, msg
    # the edges a sweep runs are read: H/R_m = 0 (every particle mobile), incidence 0
    t = [dict(r) for r in rows]
    t[1]["height-rm"] = 0.0
    run(program, write(tmp_path / "edge.csv", t, comments=["# param alpha = 0"]))
