#!/bin/bash
# test_hostile_fifteenth_layer.sh GRANWAVE SRCDIR: the fifteenth hostile pass,
# layer and sweep side. Each numbered check failed on the binary before this
# pass (d9a28a2); the guards (g) hold on both.
#  1 layer-stats --fit without beta or a_over_b: the parameters left out of the
#    B.31 fit are held at a value, and only the offset (--delta-rm) and
#    tan gamma (--gamma-deg) have an input for it. beta and a/b were held at 1,
#    a value no input gives, and reported as if measured: `--fit beta` on a
#    diagram printed "a/b 1 +- 0" and gave b = a with b_err 0 (rms 2.1 R_m),
#    `--fit tan_gamma` "beta 1 +- 0, a/b 1 +- 0", exit 0. Refused now (exit 2,
#    one line naming --fit), in the program and in Python alike.
#  2 layer-stats --fit with a name listed twice (`beta,beta` fitted beta alone)
#    or an empty item (`beta,a_over_b,`): read silently; refused as a sweep list
#    refuses them.
#  3 layer-stats --fit's refusals read "granwave layer-stats: --fit: ..." where
#    every other flag's read "granwave layer-stats --FLAG: ...".
#  4 the VTK snapshots of a clump sample did not say which disc belongs to which
#    clump: ParaView drew loose discs. Point data `body` now gives each
#    particle's rigid body; checked against the sample file's own body column
#    (the same partition of the discs, the block alone in its own) and against
#    rigidity (the distances within a body equal at the start and the end).
#  5 a sweep grid list longer than a config line (198 characters, the INI
#    reader's buffer) could not be given: 40 speeds were refused ("a line of
#    784 characters ... fewer values"), so a grid of 40 float speeds needed
#    several sweeps. A [grid] list now goes on over indented lines after a line
#    ending with a comma; the table holds every value, each case equal to the
#    single run. An indented line elsewhere, or without the comma before it, or
#    one holding a key or a section header, is still refused (g).
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
PY=/usr/bin/python3
SRC=${2:-$(dirname "${BASH_SOURCE[0]}")/..}

# a hand-made diagram table: 7 R_b x 6 H x 4 points, bouncing below a B.31
# curve (beta 1, a/b 4, offset 1, gamma 0.2 deg) and always at point 3
$PY - "$tmp/d.csv" <<'PY'
import math, sys
cols = ("x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,"
        "block_loss_first_contact,energy_error,wave_speed,t_end,steps").split(",")
T = math.tan(math.radians(0.2))
def f(x):
    K = 4 * T; u = x - 1; r = math.sqrt(u * u + K * x * x)
    return 1 + ((K * x * x / (r + u)) if u > 0 else (r - u)) / (2 * T)
with open(sys.argv[1], "w") as out:
    out.write("# hand-made layer sweep\n# param vi = 20\ncase,rb-rm,height-rm,point," + ",".join(cols) + "\n")
    k = 0
    for x in (1.25, 1.5, 2, 3, 4, 6, 8):
        for h in (2, 4, 6, 8, 10, 12):
            for p in range(4):
                b = 1 if (h < f(x) or p == 3) else 0
                v = [0.05 * p, b, 0.5, 0.6, 10, 20, 10, 12, 0.65, 2.0, 0.001, 0.6, 1e-6, float("nan"), 0.01, 100]
                out.write("%d,%g,%g,%d," % (k, x, h, p) + ",".join("%.17g" % q for q in v) + "\n")
                k += 1
PY
D=$tmp/d.csv

# --- 1: beta and a/b are always fitted
for f in beta a_over_b tan_gamma offset a_over_b,offset beta,tan_gamma; do
    refused "1: layer-stats --fit $f (beta or a/b held at 1, reported as measured)" \
        "^granwave layer-stats --fit: '$f' leaves .* out, and no input gives" layer-stats "$D" --fit "$f" --out "$tmp/o"
done
# the same refusal in Python, naming the keyword
if PYTHONPATH=$SRC/python GRANWAVE=$GW $PY - "$D" >"$tmp/py1" 2>&1 <<'PY'
import sys, granwave
try:
    granwave.layer_stats(sys.argv[1], fit="beta")
except ValueError as e:
    assert str(e).startswith("layer_stats: fit: 'beta' leaves a_over_b out"), str(e)
else:
    raise SystemExit("layer_stats(fit='beta') ran")
PY
then ok "1: granwave.layer_stats(fit='beta') refused naming fit"
else ko "1: granwave.layer_stats(fit='beta'): $(tail -3 "$tmp/py1")"; fi

# --- 2: a name twice, an empty item
refused "2: layer-stats --fit beta,beta (fitted beta alone)" \
    "^granwave layer-stats --fit: 'beta' is listed twice" layer-stats "$D" --fit beta,beta --out "$tmp/o"
refused "2: layer-stats --fit beta,a_over_b,beta" \
    "^granwave layer-stats --fit: 'beta' is listed twice" layer-stats "$D" --fit beta,a_over_b,beta --out "$tmp/o"
refused "2: layer-stats --fit beta,a_over_b, (an empty item)" \
    "^granwave layer-stats --fit: 'beta,a_over_b,' has an empty item" layer-stats "$D" --fit beta,a_over_b, --out "$tmp/o"
refused "2: layer-stats --fit ,beta,a_over_b" \
    "^granwave layer-stats --fit: ',beta,a_over_b' has an empty item" layer-stats "$D" --fit ,beta,a_over_b --out "$tmp/o"

# --- 3: the flag named as every other flag is
refused "3: layer-stats --fit BETA names the flag as the others" \
    "^granwave layer-stats --fit: unknown parameter 'BETA'" layer-stats "$D" --fit BETA --out "$tmp/o"

# --- g: the lists that keep beta and a/b still fit, the free ones as listed
for f in beta,a_over_b a_over_b,beta beta,a_over_b,offset beta,a_over_b,tan_gamma offset,beta,a_over_b,tan_gamma; do
    if timeout 60 "$GW" layer-stats "$D" --fit "$f" --json >"$tmp/g.json" 2>"$tmp/err" &&
        $PY - "$tmp/g.json" "$f" <<'PY'
import json, sys
fit = json.load(open(sys.argv[1]))["diagrams"][0]["fit"]
want = set(sys.argv[2].split(","))
assert fit is not None and set(fit["free"]) == want, fit and fit["free"]
assert abs(fit["beta"] - 1) < 0.5 and fit["beta_err"] is not None and fit["a_over_b_err"] is not None
PY
    then ok "g: layer-stats --fit $f fits $f"
    else ko "g: layer-stats --fit $f: $(head -c 300 "$tmp/err")"; fi
done

# 4: the clumps in the VTK snapshots
if timeout -s KILL 120 "$GW" layer-make --clumps --n 12 --width-rm 12 --seed 3 --t-max 0.2 --out "$tmp/c.txt" >/dev/null 2>"$tmp/err" &&
   timeout -s KILL 120 "$GW" layer-impact --sample "$tmp/c.txt" --t-max 0.004 --out "$tmp/ci" >/dev/null 2>>"$tmp/err"; then
    $PY - "$tmp/c.txt" "$tmp/ci" >"$tmp/v4" 2>&1 <<'PY'
import math, sys
def vtk(path):
    lines = open(path).read().split("\n")
    n = int(next(s for s in lines if s.startswith("POINTS")).split()[1])
    k = lines.index(next(s for s in lines if s.startswith("POINTS")))
    pts = [tuple(map(float, lines[k + 1 + i].split()[:2])) for i in range(n)]
    def arr(name):
        k = lines.index(next(s for s in lines if s.split()[:2] == ["SCALARS", name]))
        return [int(lines[k + 2 + i]) for i in range(n)]
    return pts, arr("body"), arr("block")
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
rows = [r for r in rows if len(r) == 4 and all(c.lstrip("-").replace(".", "").replace("e", "").replace("+", "").isdigit() for c in r)]
sbody = [int(r[3]) for r in rows]
p0, b0, blk = vtk(sys.argv[2] + "/snapshot_0.vtk")
p1, b1, _ = vtk(sys.argv[2] + "/snapshot_end.vtk")
assert b0 == b1, "body changed between the snapshots"
ib = blk.index(1)
grains = [i for i in range(len(b0)) if i != ib]
assert len(grains) == len(sbody), (len(grains), len(sbody))
# the same partition: sample body i <-> vtk body of the i-th grain, one to one
m = {}
for s, i in zip(sbody, grains):
    assert m.setdefault(s, b0[i]) == b0[i], "a clump split across bodies"
assert len(set(m.values())) == len(m), "two clumps share a body"
assert b0[ib] not in m.values(), "the block shares a body with a grain"
nb = len(m); nd = len(grains)
assert nb < nd, "no clump of several discs"
worst = 0
for b in set(b0):
    idx = [i for i in range(len(b0)) if b0[i] == b]
    for a in idx:
        for c in idx:
            d0 = math.dist(p0[a], p0[c]); d1 = math.dist(p1[a], p1[c])
            worst = max(worst, abs(d1 - d0))
assert worst < 1e-6, worst
print(f"{nd} discs in {nb} bodies, as the sample; distances within a body kept to {worst:.1e} m")
PY
    [ $? -eq 0 ] && ok "4: VTK body of a clump sample: $(cat "$tmp/v4")" || ko "4: VTK body: $(tail -2 "$tmp/v4")"
else ko "4: clump sample and impact: $(head -c 300 "$tmp/err")"; fi

# 5: a [grid] list over several lines
$PY - "$tmp/long.ini" "$tmp" <<'PY'
import sys
v = [round(0.05 + 0.025 * k, 3) for k in range(39)]
lines, line = [], "vimp = "
for j, t in enumerate("%g" % x for x in v):
    item = t + ("," if j < len(v) - 1 else "")
    if len(line) + len(item) > 120:
        lines.append(line.rstrip()); line = "    "
    line += item + " "
lines.append(line.rstrip())
open(sys.argv[1], "w").write("[sweep]\nmodel = chain\n[grid]\nn = 3\n" + lines[0] + " ; the speeds\n" +
                             "\n".join(lines[1:2]) + "\n  ; a comment between\n\n" + "\n".join(lines[2:]) +
                             "\n[params]\nsolver = rk4\n")
open(sys.argv[2] + "/vimp.txt", "w").write("\n".join("%g" % x for x in v) + "\n")
PY
if timeout -s KILL 120 "$GW" sweep "$tmp/long.ini" --out "$tmp/sl" --jobs 2 >/dev/null 2>"$tmp/err"; then
    got=$(awk -F, '!/^#/ && $1 != "case" {print $3}' "$tmp/sl/results.csv")
    one=$(timeout -s KILL 60 "$GW" chain --n 3 --vimp 0.975 --solver rk4 --json | $PY -c "import json,sys; print(repr(json.load(sys.stdin)['f_max']))")
    row=$(awk -F, '!/^#/ && $3 == "0.975" {print $4}' "$tmp/sl/results.csv")
    [ "$got" = "$(cat "$tmp/vimp.txt")" ] && $PY -c "import sys; sys.exit(0 if float('$row') == float('$one') else 1)" &&
        ok "5: a [grid] list over 4 lines runs its 39 speeds (case 0.975: f_max $row, the single run's)" ||
        ko "5: long list: speeds $(echo $got | head -c 100) / f_max $row against $one"
else ko "5: sweep of a list over several lines: $(head -c 300 "$tmp/err")"; fi
# (g) what an indented line may not be
printf '[sweep]\nmodel = chain\nout = %s\n[grid]\nvimp = 0.1, 0.2\n  0.3\n' "$tmp/x" >"$tmp/g1.ini"
printf '[sweep]\nmodel = chain\nout = %s\n[grid]\nvimp = 0.1,\n  n = 3\n' "$tmp/x" >"$tmp/g2.ini"
printf '[sweep]\nmodel = chain\nout = %s\n[grid]\nvimp = 0.1,\n  [params]\nsolver = rk4\n' "$tmp/x" >"$tmp/g3.ini"
printf '[sweep]\nmodel = chain\nout = %s\n[params]\nvimp = 0.1,\n  0.2\n[grid]\nn = 1:2\n' "$tmp/x" >"$tmp/g4.ini"
printf '[sweep]\nmodel = chain\nout = %s\n[grid]\nvimp = 0.1, 0.2,\n' "$tmp/x" >"$tmp/g5.ini"
for g in "g1:6: an indented line: the config reader takes it as more of the value of 'vimp' (line 5)" \
         "g2:6: an indented" \
         "g3:6: an indented" \
         "g4:6: an indented line: the config reader takes it as more of the value of 'vimp' (line 5)" \
         "g5:5: vimp: empty value in list"; do
    f=${g%%:*}
    cpu_run 30 "$GW" sweep "$tmp/$f.ini" >/dev/null 2>"$tmp/err"
    rc=$?
    [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -qF "$tmp/$f.ini:${g#*:}" "$tmp/err" && [ ! -e "$tmp/x" ] &&
        ok "g: $f refused: $(cut -c1-110 "$tmp/err")" || ko "g: $f: exit $rc $(cat "$tmp/err")"
done

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
