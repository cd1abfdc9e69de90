#!/bin/bash
# test_layer_stats_cli.sh GRANWAVE SRCDIR: `granwave layer-stats` (issue 5,
# docs/physics.md 2.3 and 2.5).
#  - bad input (missing file, a non-numeric cell, a missing column, a short
#    row, a bad option value) exits 2 with one line on stderr naming the file
#    and line (or the option), and writes nothing (no --out directory);
#  - a synthetic table whose rows bounce when H < B.31(R_b/R_m) (beta = 1,
#    a/b = 4, delta*/(2 R_m) = 1, gamma = 0.2 deg) gives the boundary and
#    R_crit computed independently here in Python, and a fit whose beta and
#    a/b lie within 3 of their reported standard errors of the truth (the grid
#    spacing in H is 3 R_m, so the placed H* scatter by about 1 R_m about the
#    curve and the errors come from that scatter; beta_err < 0.5 keeps the
#    check from being vacuous); every output file carries the version and
#    the input path;
#  - walls kept / removed are paired per rb-rm (flags written false/true),
#    and the binary table holds per R_b/R_m the mean first-contact loss with
#    the incidence of the "# param" line and the two closed forms;
#  - a real tiny sweep (model layer, 2 R_b x 2 H x 3 points on a 40-disc
#    sample) runs through layer-stats: the group shares and means of e over
#    the bouncing points equal those recomputed in Python from results.csv.
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

COLS="x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps"
ROW="0,1,0.5,0.6,10,20,10,12,0.1,0.3,0.001,0.6,1e-6,nan,0.01,100"

# bad NAME EXPECTED-TEXT [extra args]: the table in $tmp/NAME.csv must be refused
bad() {
    local name=$1 want=$2; shift 2
    "$GW" layer-stats "$tmp/$name.csv" --out "$tmp/o_$name" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?
    if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "$want" "$tmp/err" \
        && [ ! -e "$tmp/o_$name" ] && [ ! -s "$tmp/out" ]; then
        ok "$name -> exit 2, nothing written: $(cat "$tmp/err")"
    else
        ko "$name -> exit $rc, stderr: $(cat "$tmp/err"), out dir: $(ls "$tmp/o_$name" 2>&1 | head -1)"
    fi
}
bad missing "missing.csv: cannot open"
printf '# c\ncase,point,%s\n0,0,%s\n1,1,0,1,0.5,abc,10,20,10,12,0.1,0.3,0.001,0.6,1e-6,nan,0.01,100\n' "$COLS" "$ROW" >"$tmp/cell.csv"
bad cell "cell.csv:4: column e: 'abc'"
printf 'case,point,%s\n0,0,%s\n' "${COLS/,penetration_rm/}" "${ROW/,0.3,/,}" >"$tmp/column.csv"
bad column "column.csv:1: header has no column 'penetration_rm'"
printf 'case,point,%s\n0,0,%s\n1,1,0,1\n' "$COLS" "$ROW" >"$tmp/short.csv"
bad short "short.csv:3: 4 cells, header has 18"
printf 'case,point,%s\n0,0,%s\n' "$COLS" "$ROW" >"$tmp/good.csv"
bad good "criterion" --criterion 1.5
bad good "--fit: unknown parameter 'gamma'" --fit beta,gamma

# synthetic diagram: bounce iff H < f(R_b/R_m) + noise that never crosses a grid cell
$PY - "$tmp/syn.csv" "$tmp/expect.txt" <<'PY'
import math, sys
cols = "x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps".split(",")
T = math.tan(math.radians(0.2))
def f(x, d=1.0, beta=1.0, ab=4.0):
    K = ab * T; u = x - beta; r = math.sqrt(u * u + K * x * x)
    return d + ((K * x * x / (r + u)) if u > 0 else (r - u)) / (2 * T)
xs, hs, npt = [0.5, 0.9, 1.5, 2, 3, 4, 6, 8], [3, 6, 9, 12, 15, 18, 21], 4
with open(sys.argv[1], "w") as out:
    out.write("# synthetic layer sweep\n# param vi = 20\ncase,rb-rm,height-rm,point," + ",".join(cols) + "\n")
    k = 0
    for x in xs:
        for h in hs:
            for p in range(npt):
                # points 0-2 follow the curve, point 3 always bounces: share 1 or 1/4
                b = 1 if (h < f(x) or p == 3) else 0
                v = [0.05 * p, b, 0.5, 0.6, 10, 20, 10, 12, 0.65, 2.0, 0.001, 0.6, 1e-6, float("nan"), 0.01, 100]
                out.write("%d,%g,%g,%d," % (k, x, h, p) + ",".join("%.17g" % q for q in v) + "\n"); k += 1
# expected boundary: share 1 below f, 1/4 above -> H* = h_lo + (1 - 0.75)/(1 - 0.25) (h_hi - h_lo)
with open(sys.argv[2], "w") as e:
    for x in xs:
        below = [h for h in hs if h < f(x)]
        above = [h for h in hs if h >= f(x)]
        if not above: e.write("%g above nan\n" % x)
        elif not below: e.write("%g below nan\n" % x)
        else: e.write("%g cross %.12g\n" % (x, max(below) + (min(above) - max(below)) / 3))
    allb = [all(h < f(x) for h in hs) for x in xs]
    k = allb.index(False)  # columns up to k - 1 bounce at every H
    e.write("rcrit %g %g\n" % (xs[k - 1], xs[k]))
PY
"$GW" layer-stats "$tmp/syn.csv" --out "$tmp/syn" --json >"$tmp/syn.json" 2>"$tmp/err"; rc=$?
[ $rc -eq 0 ] && ok "synthetic table: exit 0" || ko "synthetic table: exit $rc: $(cat "$tmp/err")"
$PY - "$tmp/syn.json" "$tmp/expect.txt" "$tmp/syn" "$tmp/syn.csv" "$("$GW" version)" <<'PY' && ok "synthetic diagram: boundary, R_crit bracket, beta fit, files carry version and input" || ko "synthetic diagram"
import json, math, os, sys
j = json.load(open(sys.argv[1]))
bad = []
d = j["diagrams"][0]
exp = [l.split() for l in open(sys.argv[2])]
rc = [float(v) for v in exp.pop()[1:]]
for b, (x, kind, h) in zip(d["boundary"], exp):
    if b["kind"] != kind or (kind == "cross" and abs(b["h_star"] - float(h)) > 1e-9):
        bad.append("x=%s: got %s %s, expected %s %s" % (x, b["kind"], b["h_star"], kind, h))
if [d["r_crit"], d["r_crit_upper"]] != rc:
    bad.append("R_crit %s..%s" % (d["r_crit"], d["r_crit_upper"]))
fit = d["fit"]
if fit is None or abs(fit["beta"] - 1) > 3 * fit["beta_err"] or fit["beta_err"] > 0.5 \
        or abs(fit["a_over_b"] - 4) > 3 * fit["a_over_b_err"] or fit["free"] != ["beta", "a_over_b"] or abs(fit["offset"] - 1) > 1e-12:
    bad.append("fit %s" % fit)
if len(j["groups"]) != 56 or any(g["n_points"] != 4 for g in j["groups"]):
    bad.append("groups")
version = sys.argv[5].split()[1]
for name in ("groups.csv", "convergence.csv", "binary.csv", "walls.csv", "diagram.csv"):
    head = open(os.path.join(sys.argv[3], name)).read().split("\n")[:3]
    if head[0] != "# granwave %s layer-stats" % version or head[2] != "# input: " + sys.argv[4]:
        bad.append(name + " lacks version or input path: %s" % head)
bf = json.load(open(os.path.join(sys.argv[3], "boundary_fit.json")))
if bf["version"] != version or bf["input"] != sys.argv[4] or bf["diagrams"][0]["fit"] != fit:
    bad.append("boundary_fit.json: version, input or fit differ")
print("\n".join(bad) or "diagram ok: " + json.dumps({k: fit[k] for k in ("beta", "beta_err", "a_over_b", "a_over_b_err", "rms_residual")}))
sys.exit(1 if bad else 0)
PY

# walls side by side and the binary check: rb-rm x remove-walls (false/true, as
# the sweep model writes flags) x 2 points; block loss and bounces chosen by hand
printf '# param alpha = 30\ncase,rb-rm,remove-walls,point,%s\n' "$COLS" >"$tmp/walls.csv"
k=0
for rb in 1 2; do for w in false true; do for p in 0 1; do
    b=$([ "$w" = true ] && [ "$p" = 1 ] && echo 0 || echo 1)      # walls removed: 1 of 2 bounce
    loss=$(echo "$rb $p" | awk '{print 0.1 * $1 + 0.2 * $2}')     # mean over a rb: 0.1 rb + 0.1
    echo "$k,$rb,$w,$p,0,$b,0.5,0.6,10,20,10,12,0.1,0.3,0.001,$loss,1e-6,nan,0.01,100" >>"$tmp/walls.csv"
    k=$((k+1))
done; done; done
"$GW" layer-stats "$tmp/walls.csv" --json >"$tmp/walls.json" 2>"$tmp/err" || ko "walls table: $(cat "$tmp/err")"
$PY - "$tmp/walls.json" <<'PY' && ok "walls paired (kept vs removed) per rb-rm, rebound energy 0.36 / 0.18; binary loss per R_b/R_m at alpha 30 beside 4r^2/(1+r^2)^2, 4r^3/(1+r^3)^2" || ko "walls / binary"
import json, sys
j = json.load(open(sys.argv[1]))
bad = []
w = j["walls"]
if len(w) != 2 or [p["keys"] for p in w] != [{"rb-rm": 1}, {"rb-rm": 2}]:
    bad.append("pairs %s" % [p["keys"] for p in w])
for p in w:
    if p["walls"]["bounce_share"] != 1 or p["walls_removed"]["bounce_share"] != 0.5 or p["walls_removed"]["bouncing"]:
        bad.append("shares %s" % p)
    # rebound energy e^2 = 0.36 where the block bounces, 0 where it does not
    if abs(p["walls"]["rebound_energy_mean"] - 0.36) > 1e-12 or abs(p["walls_removed"]["rebound_energy_mean"] - 0.18) > 1e-12:
        bad.append("rebound energy %s" % p)
b = {x["rb_rm"]: x for x in j["binary"]}
for r in (1, 2):
    x = b.get(r)
    if not x or x["alpha"] != 30 or x["block_loss_first_contact"]["n"] != 4 \
            or abs(x["block_loss_first_contact"]["mean"] - (0.1 * r + 0.1)) > 1e-12 \
            or abs(x["binary_disc"] - 4 * r**2 / (1 + r**2)**2) > 1e-15 or abs(x["binary_sphere"] - 4 * r**3 / (1 + r**3)**2) > 1e-15:  # r >= 1
        bad.append("binary %s" % x)
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY

# a real tiny sweep through layer-stats
"$GW" layer-make --n 40 --width-rm 14 --seed 2 --out "$tmp/S.txt" >/dev/null || { echo "FAIL: layer-make"; exit 1; }
cat >"$tmp/s.ini" <<CFG
[sweep]
model = layer
[grid]
rb-rm = 0.8, 2
height-rm = 2, 4
point = 0:2
[params]
sample = $tmp/S.txt
points = 3
t-max = 0.02
CFG
"$GW" sweep "$tmp/s.ini" --out "$tmp/sw" --quiet --jobs 2 >/dev/null 2>&1 || ko "layer sweep failed"
"$GW" layer-stats "$tmp/sw/results.csv" --json >"$tmp/real.json" 2>"$tmp/err"; rc=$?
[ $rc -eq 0 ] && ok "layer-stats on a real sweep: exit 0" || ko "real sweep: exit $rc: $(cat "$tmp/err")"
$PY - "$tmp/real.json" "$tmp/sw/results.csv" <<'PY' && ok "real sweep: shares and mean e per group equal the recomputation from results.csv" || ko "real sweep statistics"
import csv, json, math, sys
j = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#")))
bad = []
if len(j["groups"]) != 4:
    bad.append("%d groups" % len(j["groups"]))
for g in j["groups"]:
    k = g["keys"]
    sel = [r for r in rows if float(r["rb-rm"]) == k["rb-rm"] and float(r["height-rm"]) == k["height-rm"]]
    nb = sum(float(r["bounced"]) == 1 for r in sel)
    nd = sum(not math.isnan(float(r["bounced"])) for r in sel)  # decided
    # e of a bouncing row is nan when its run ended before T_f: left out
    es = [float(r["e"]) for r in sel if float(r["bounced"]) == 1 and math.isfinite(float(r["e"]))]
    me = sum(es) / len(es) if es else None
    sd = g["bounce_share_decided"]
    if len(sel) != 3 or g["n_bounced"] != nb or abs(g["bounce_share"] - nb / 3) > 1e-15 or g["n_valid"] != nd \
            or (nd and abs(sd - nb / nd) > 1e-15) or (not nd and sd is not None) \
            or abs(g["bounce_share_high"] - (nb + 3 - nd) / 3) > 1e-15:
        bad.append("share %s" % k)
    if (me is None) != (g["e"]["mean"] is None) or (me is not None and abs(g["e"]["mean"] - me) > 1e-12):
        bad.append("mean e %s: %s vs %s" % (k, g["e"]["mean"], me))
print("\n".join(bad) or "; ".join("R_b %g H %g: share %.2f e %s" % (g["keys"]["rb-rm"], g["keys"]["height-rm"],
                                  g["bounce_share"], g["e"]["mean"]) for g in j["groups"]))
sys.exit(1 if bad else 0)
PY
test_summary
