#!/bin/bash
# test_layer_side_walls.sh GRANWAVE SRCDIR: one side wall taken away from the
# command line (layer-impact --side-walls both|left|right|none, session 44:
# before, only --remove-walls, which takes the floor away too), its refusals,
# and layer-make's word on a clump pile that has not come to rest.
# `layer-make --clumps --width-rm 6 --n 40 --seed 4` holds its weight steady
# from 3 s on (floor 2.25, side walls -1.25 at the median, centre of mass
# within 3 mm) while its last clump dropped rolls to and fro on its top, a
# median 0.82 of E_k, until 6.41 s (settled then at --t-max 8). Checks:
#  1 at --t-max 3 the did-not-settle warning says that most of E_k (0.9 or
#    more) is in the one grain that moves most, on a pile its floor and side
#    walls carry (before: "E_k = ... still above --ke-threshold", no more);
#  2 layer-impact --side-walls left on that sample is refused (exit 2, one
#    line naming --side-walls, the floor's and the walls' shares, nothing on
#    stdout): its side walls help hold it;
#  3 --side-walls with --remove-walls (other than both) is refused, naming
#    both; an unknown value is refused naming the choices;
#  4 on the stored 300-disc sample, --side-walls left with the block thrown
#    right (--x 7.5 --alpha 60): the block leaves the layer beyond its right
#    side (fell_off, bounced false), the settings name side_walls left;
#  5 --side-walls both gives the default's JSON (but wall_time_ms), with no
#    side_walls key (every other run's JSON unchanged).
#  6 (session 45) layer-make's --json gives that share, ke_top_share, the
#    warning's value to 2 digits (it was in the warning only);
#  7 (session 45) a row of 5 discs on the floor pressed between its walls with
#    twice its weight (the floor carrying 1.00 of it): --side-walls left is
#    refused naming the right wall's push (the floor's share alone passed
#    it), both walls kept it runs.
# About 12 s of CPU (the pluviation to 3 s).
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
STORED=$SRC/data/measured/restitution_full/sample.txt

# --- 1 the clump rolling on a pile at rest ---
cpu_run 120 "$GW" layer-make --clumps --width-rm 6 --n 40 --seed 4 --t-max 3 --json --quiet --out p.txt \
    >p.json 2>p.err
share=$(grep -oE '[0-9.]+ of it in the one grain that moves most' p.err | cut -d' ' -f1)
if [ -n "$share" ] && /usr/bin/python3 -c "import sys; sys.exit(0 if float('$share') >= 0.9 else 1)" &&
    grep -q "one clump or disc still rolling or rocking on a pile at rest (raise --t-max)" p.err &&
    grep -qE "while its floor and side walls carry (0\.9[0-9]*|1|1\.0[0-9]*) of the pile's weight" p.err; then
    ok "--t-max 3: $share of E_k in one grain, the pile's supports carrying its weight"
else
    ko "--t-max 3: the warning does not name the moving grain: $(head -c 500 p.err)"
fi

# --- 2 refused without a side wall: the walls help hold the pile ---
cpu_run 60 "$GW" layer-impact --sample p.txt --side-walls left --t-max 1e-4 --json --quiet >l.json 2>l.err
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <l.err)" = 1 ] && [ ! -s l.json ] && grep -q -- "--side-walls: left:" l.err &&
    grep -qE "the floor carries 2\.2[0-9]* of its weight and the side walls -1\.[0-9]*" l.err &&
    grep -q "without its right wall it is not at rest" l.err; then
    ok "--side-walls left on a pile its walls hold: refused, $(grep -oE 'the floor carries [^;]*' l.err)"
else
    ko "--side-walls left on a pile its walls hold: exit $rc, $(head -c 400 l.err)"
fi

# --- 3 with --remove-walls, and an unknown value ---
cpu_run 60 "$GW" layer-impact --sample "$STORED" --side-walls right --remove-walls --json --quiet >r.json 2>r.err
rc=$?
if [ $rc -eq 2 ] && [ ! -s r.json ] && grep -q -- "--side-walls: right is given with remove-walls" r.err; then
    ok "--side-walls right --remove-walls: refused naming both"
else
    ko "--side-walls right --remove-walls: exit $rc, $(head -c 300 r.err)"
fi
cpu_run 60 "$GW" layer-impact --sample "$STORED" --side-walls middle --json --quiet >u.json 2>u.err
rc=$?
if [ $rc -eq 2 ] && [ ! -s u.json ] && grep -q -- "--side-walls: unknown value 'middle' (both left right none)" u.err; then
    ok "--side-walls middle: refused naming the choices"
else
    ko "--side-walls middle: exit $rc, $(head -c 300 u.err)"
fi

# --- 4 the right wall taken away: the block leaves beyond it ---
cpu_run 60 "$GW" layer-impact --sample "$STORED" --side-walls left --x 7.5 --alpha 60 --json --quiet >s.json 2>s.err
rc=$?
v=$(jq_py s.json 'd["bounced"] is False and d["fell_off"] == "beyond its right side" and d["settings"]["side_walls"] == "left"' 2>/dev/null)
if [ $rc -eq 0 ] && [ "$v" = True ] && grep -q "warning: the block fell off the layer (beyond its right side" s.err; then
    ok "--side-walls left, block thrown right: fell off beyond its right side at t = $(jq_py s.json 'd["t_end"]') s"
else
    ko "--side-walls left, block thrown right: exit $rc, $(head -c 300 s.json) $(head -c 300 s.err)"
fi

# --- 5 both is the default, bit for bit ---
cpu_run 60 "$GW" layer-impact --sample "$STORED" --t-max 0.01 --json --quiet >d.json 2>d.err
rc0=$?
cpu_run 60 "$GW" layer-impact --sample "$STORED" --t-max 0.01 --side-walls both --json --quiet >b.json 2>b.err
rc=$?
v=$(/usr/bin/python3 - d.json b.json <<'PY'
import json, sys
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k != "wall_time_ms"}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
a, b = (json.load(open(p)) for p in sys.argv[1:3])
print(strip(a) == strip(b) and "side_walls" not in a["settings"] and "side_walls" not in b["settings"])
PY
)
if [ $rc0 -eq 0 ] && [ $rc -eq 0 ] && [ "$v" = True ]; then
    ok "--side-walls both: the default's JSON, no side_walls key"
else
    ko "--side-walls both: exit $rc0/$rc, equal and keyless: $v $(head -c 300 b.err)"
fi

# --- 6 the grain's share in layer-make's JSON ---
v=$(jq_py p.json 'd["converged"] is False and "%.2g" % d["ke_top_share"] == "'"$share"'"' 2>/dev/null)
if [ -n "$share" ] && [ "$v" = True ]; then
    ok "layer-make --json: ke_top_share $(jq_py p.json 'd["ke_top_share"]'), the warning's $share"
else
    ko "layer-make --json: ke_top_share $(jq_py p.json 'd.get("ke_top_share")' 2>&1 | tail -1) against the warning's '$share'"
fi

# --- 7 a pile wedged between its walls, its floor carrying its weight (session 45) ---
# 5 discs (r = 0.1 m) in a row on the floor, each with the floor overlap that
# carries its weight, pressed between the walls with twice the row's weight
# (Hertz K_n = 2 sqrt(2 r) G / (3 (1 - nu)), the default material): the floor's
# share alone (1) passed it, as it passed `layer-make --clumps --width-rm 6
# --n 40 --seed 1` (floor 1.01, walls pushing with 2.2 and 2.5 times its weight)
/usr/bin/python3 - <<'PY'
import math
G, nu, rho, g, r, n = 40e9, 0.25, 2650.0, 9.81, 0.1, 5
kn, mg = 2 * math.sqrt(2 * r) * G / (3 * (1 - nu)), rho * math.pi * r * r * g
uf, uw = (mg / kn) ** (2 / 3), (2 * n * mg / kn) ** (2 / 3)
x = [r - uw + i * (2 * r - uw) for i in range(n)]
with open("row.txt", "w") as f:
    f.write("granwave-layer-sample 1\n# units: metres; lines after 'n' are: x y r\n")
    f.write(f"width {x[-1] + r - uw!r}\nrm {r!r}\nvolume_ratio 1\nseed 0\nmass_law disc\nn {n}\n")
    for xi in x:
        f.write(f"{xi!r} {r - uf!r} {r!r}\n")
PY
cpu_run 60 "$GW" layer-impact --sample row.txt --side-walls left --t-max 1e-3 --json --quiet >w.json 2>w.err
rc=$?
cpu_run 60 "$GW" layer-impact --sample row.txt --t-max 1e-3 --json --quiet >wb.json 2>wb.err
rcb=$?
if [ $rc -eq 2 ] && [ "$(wc -l <w.err)" = 1 ] && [ ! -s w.json ] &&
    grep -q -- "--side-walls: left: the sample's pile leans on its right wall (at t = 0 it pushes the pile with 2 of its weight" w.err &&
    grep -q "while the floor carries 1; a wall taken away may carry at most 1" w.err && [ $rcb -eq 0 ]; then
    ok "a row pressed between its walls: --side-walls left refused naming the right wall's push, both runs"
else
    ko "a row pressed between its walls: exit $rc (both: $rcb), $(head -c 400 w.err) $(head -c 200 wb.err)"
fi

test_summary test_layer_side_walls
