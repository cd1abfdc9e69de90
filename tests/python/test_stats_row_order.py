"""`granwave layer-stats` on one table with its rows in another order, and on
diagrams without a boundary.

1. The rows of a sweep table shuffled (case numbers kept) give the same files,
   byte for byte but for the lines naming the input (command, path, hash), and
   the same JSON. The binary table listed its (R_b/R_m, incidence) rows in
   the order the table first showed them, and summed each row's losses in
   table order: a shuffled table gave another order of binary.csv (and sums
   that could differ in their last bits). Its rows are now in increasing
   R_b/R_m, then incidence, each over its rows in case order.
2. The binary rows are in increasing R_b/R_m even when the sweep ran its grid
   downwards.
3. A diagram where every column bounces at every H (or at none) has no
   boundary: the fit says so. It said "no offset: no boundary crossing with a
   penetration (give --delta-rm)", and with --delta-rm it then said "0
   boundary point(s) for 2 free parameter(s)".
"""
import json
import math
import random
import subprocess

COLS = ["x_impact", "bounced", "e_n", "e", "alpha_r", "penetration", "penetration_rm",
        "block_loss_first_contact", "dissipated_first_contact"]


def table(xs, hs, points, bounce, seed=1):
    rng = random.Random(seed)
    rows, case = [], 0
    for x in xs:
        for h in hs:
            for p in range(points):
                b = bounce(x, h, rng)
                e = rng.uniform(0.1, 0.9)
                rows.append([case, x, h, p, 0.05 * p, b, e / 2 if b else math.nan, e if b else math.nan,
                             rng.uniform(0, 80) if b else math.nan, 0.001 * (1 + h / x), 0.03 * (1 + h / x),
                             rng.uniform(0, 1), rng.uniform(0, 1)])
                case += 1
    return rows


def write(path, rows):
    lines = [",".join(["case", "rb-rm", "height-rm", "point"] + COLS)]
    for r in rows:
        lines.append(",".join([str(r[0]), repr(float(r[1])), repr(float(r[2])), str(r[3])] +
                              ["nan" if isinstance(v, float) and math.isnan(v) else repr(float(v)) for v in r[4:]]))
    path.write_text("\n".join(lines) + "\n")
    return path


def boundary(x, h, rng):
    return 1.0 if h < 3 + 1.5 * abs(x - 3) + 2 / x + rng.uniform(-2, 2) else 0.0


def run(program, *args):
    p = subprocess.run([program, "layer-stats", *map(str, args)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return p.stdout


def body(path):
    """A file without the lines that name the input."""
    keep = []
    for line in path.read_text().splitlines():
        if line.startswith(("# command", "# input")) or line.lstrip().startswith(('"command"', '"input')):
            continue
        keep.append(line)
    return keep


def test_shuffled_rows_give_the_same_files(program, tmp_path):
    rows = table([0.5, 1, 1.5, 2, 3, 4, 6, 8], [2, 4, 6, 8, 12, 16, 20], 10, boundary)
    shuffled = rows[:]
    random.Random(5).shuffle(shuffled)
    a, b = write(tmp_path / "a.csv", rows), write(tmp_path / "b.csv", shuffled)
    for fit in ("beta,a_over_b", "beta,a_over_b,offset,tan_gamma"):
        oa, ob = tmp_path / f"oa{len(fit)}", tmp_path / f"ob{len(fit)}"
        run(program, a, "--fit", fit, "--out", oa)
        run(program, b, "--fit", fit, "--out", ob)
        names = sorted(p.name for p in oa.iterdir())
        assert names == sorted(p.name for p in ob.iterdir())
        for n in names:
            assert body(oa / n) == body(ob / n), f"{fit}: {n} differs"
        ja, jb = json.loads(run(program, a, "--fit", fit, "--json")), json.loads(run(program, b, "--fit", fit, "--json"))
        for k in ("command", "input", "input_fnv1a64"):
            ja.pop(k), jb.pop(k)
        assert ja == jb, fit


def test_binary_rows_in_increasing_rb(program, tmp_path):
    rows = table([6, 4, 2, 1, 0.5], [2, 8], 3, boundary)  # a grid run downwards
    j = json.loads(run(program, write(tmp_path / "d.csv", rows), "--json"))
    rb = [r["rb_rm"] for r in j["binary"]]
    assert rb == sorted(rb) == [0.5, 1, 2, 4, 6]


def test_no_boundary_says_so(program, tmp_path):
    for name, b in (("all", 1.0), ("none", 0.0)):
        t = write(tmp_path / f"{name}.csv", table([1, 2, 3], [2, 4, 8], 2, lambda x, h, rng, b=b: b))
        for extra in ((), ("--delta-rm", "1")):
            d = json.loads(run(program, t, "--json", *extra))["diagrams"][0]
            assert d["fit"] is None
            assert d["fit_reason"].startswith("no boundary crossing"), d["fit_reason"]
