#!/bin/bash
# test_settling_clumps.sh GRANWAVE SRCDIR: the clump mass a pile settled
# under enters the settling check (issue 18, class 5: silent wrong answers).
# layer-make records it (material.clump_mass in its settings line, the
# library's clump-mass, and the sample's own clump_mass line); a clump's
# union weighs less than its members' sum (overlaps counted once), so a clump
# pile settled with one and hit with the other (--clump-mass) carries
# q = W_settled / W_impact of its weight at rest. Before, q was computed disc
# by disc, came out 1, and the run said nothing. Checked, on a 20-clump pile
# settled with union and one settled with sum (seed 1):
#  1 union hit with --clump-mass sum: exit 0, one warning line naming
#    "clump-mass union against the impact's sum", impact.json's
#    settings.sample_settled.clump_mass "union" and load_ratio q equal to the
#    clumps' union area over their discs' summed area, computed here column
#    by column (exact chords, 20000 columns a clump), to 1e-5; q < 1;
#  2 sum hit with --clump-mass union: the warning, q the inverse ratio (> 1);
#  3 matched (the sample's own clump mass, or given as it is): no settling
#    warning, q = 1;
#  4 a settings line with clump_mass "cube", or union with mass_law sphere,
#    is refused by the reader (exit 2, the file, line and key); the library's
#    flat line (clump-mass) is read the same: union hit with sum warns with
#    the same q, "cube" is refused;
#  5 a layer sweep with clump-mass = sum over the union pile: its rows'
#    settling_warning 1 and settled_load_ratio q.
# All 9 checks fail on the code before (the matched runs too: its
# impact.json's sample_settled had no clump_mass).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
PY=/usr/bin/python3

mk() { make_sample "$1" --n 20 --clumps --seed 1 "${@:2}"; }
mk u.txt --clump-mass union
mk s.txt

# the clumps' union area over their summed area, here (independent of the
# program's moments: chords merged per column, in Python)
ratio() {
    $PY - "$1" <<'PY'
import math, sys
from collections import defaultdict
cl, n = defaultdict(list), None
for line in open(sys.argv[1]):
    f = line.split()
    if line.startswith("#") or not f:
        continue
    if n is None:
        if f[0] == "n":
            n = int(f[1])
        continue
    if f[0] == "springs": # the contacts' springs follow the particles
        break
    cl[int(f[3])].append((float(f[0]), float(f[1]), float(f[2])))
union = summed = 0.0
for m in cl.values():
    summed += sum(math.pi * r * r for _, _, r in m)
    lo, hi = min(x - r for x, _, r in m), max(x + r for x, _, r in m)
    k = 20000
    dx = (hi - lo) / k
    for c in range(k):
        x = lo + (c + 0.5) * dx
        iv = sorted((y - math.sqrt(r * r - (x - xc) ** 2), y + math.sqrt(r * r - (x - xc) ** 2))
                    for xc, y, r in m if abs(x - xc) < r)
        a, b, tot = None, None, 0.0
        for s, e in iv:
            if a is None or s > b:
                tot += (b - a) if a is not None else 0.0
                a, b = s, e
            else:
                b = max(b, e)
        tot += (b - a) if a is not None else 0.0
        union += tot * dx
print(repr(union / summed))
PY
}
r=$(ratio u.txt)

check_q() { # WHAT FILE WANT_Q WANT_CLUMP ARGS...
    local what=$1 want=$3 clump=$4; shift 4
    runs_json "$what" q.json layer-impact --t-max 0.002 "$@" || return
    local got n
    got=$(jq_py q.json "d['settings']['sample_settled']['clump_mass'], abs(d['settings']['sample_settled']['load_ratio'] / $want - 1) < 1e-5, d['settings']['sample_settled']['load_ratio']")
    n=$(grep -c "warning: the sample settled with clump-mass" "$tmp/stderr")
    if [ "$clump" = none ]; then
        [ "$n" = 0 ] && ! grep -q "settled with" "$tmp/stderr" && [ "${got% *}" = "${got%% *} True" ] &&
            ok "$what: no settling warning, q $want" || ko "$what: $n warnings, JSON $got: $(cat "$tmp/stderr")"
    else
        [ "$n" = 1 ] && grep -q "clump-mass $clump" "$tmp/stderr" && [ "${got% *}" = "union True" ] &&
            ok "$what: warns (clump-mass $clump), q = $want to 1e-5 (JSON: $got)" ||
            ko "$what: $n warnings, JSON $got (want q $want): $(cat "$tmp/stderr")"
    fi
}
# 1, 2
check_q "union pile hit with --clump-mass sum" x "$r" "union against the impact's sum" --sample u.txt --clump-mass sum
rs=$(ratio s.txt)
runs_json "sum pile hit with --clump-mass union" q2.json layer-impact --t-max 0.002 --sample s.txt --clump-mass union &&
    [ "$(grep -c "warning: the sample settled with clump-mass sum against the impact's union" "$tmp/stderr")" = 1 ] &&
    [ "$(jq_py q2.json "d['settings']['sample_settled']['clump_mass'], abs(d['settings']['sample_settled']['load_ratio'] * $rs - 1) < 1e-5, d['settings']['sample_settled']['load_ratio'] > 1")" = "sum True True" ] &&
    ok "sum pile hit with --clump-mass union: warns, q = 1/$rs" || ko "sum pile hit with union: $(cat "$tmp/stderr") $(jq_py q2.json "d['settings']['sample_settled']" 2>&1)"
# 3
check_q "union pile, its own clump mass" x 1 none --sample u.txt
check_q "union pile, --clump-mass union" x 1 none --sample u.txt --clump-mass union

# 4: the reader
sed 's/"clump_mass":"union"/"clump_mass":"cube"/' u.txt >bad_cube.txt
sed 's/"mass_law":"disc (unit thickness)"/"mass_law":"sphere"/' u.txt >bad_sphere.txt
grep -q '"clump_mass":"cube"' bad_cube.txt && grep -q '"mass_law":"sphere"' bad_sphere.txt ||
    echo "NOTE: the settings line's spelling changed: $(grep '^# settings' u.txt | head -c 300)"
refused "settings line with clump_mass cube" "sample 'bad_cube.txt': line [0-9]+: layer-make's settings line has a clump mass that is neither sum nor union: clump_mass" \
    layer-impact --sample bad_cube.txt --t-max 0.002 --out "$tmp/o"
refused "settings line with union and sphere" "sample 'bad_sphere.txt': line [0-9]+: .*clump mass union with mass law sphere" \
    layer-impact --sample bad_sphere.txt --t-max 0.002 --out "$tmp/o"

# the library's dialect of the line (flat rows, as gw_layer_make_run and
# Python's layer_make write it): clump-mass read the same
flat='# settings: {"shear-modulus":40000000000,"poisson":0.25,"friction":30,"density":2650,"gravity":9.81,"mass-law":"disc","clump-mass":"CM"}'
sed "s|^# settings: .*|${flat/CM/union}|" u.txt >lib_u.txt
sed "s|^# settings: .*|${flat/CM/cube}|" u.txt >lib_cube.txt
check_q "union pile, the library's line, hit with --clump-mass sum" x "$r" "union against the impact's sum" \
    --sample lib_u.txt --clump-mass sum
refused "the library's line with clump-mass cube" "sample 'lib_cube.txt': line [0-9]+: layer-make's settings line has a clump mass that is neither sum nor union: clump-mass" \
    layer-impact --sample lib_cube.txt --t-max 0.002 --out "$tmp/o"

# 5: a sweep's rows
settling_sweep_ini sw.ini "$tmp/u.txt" "clump-mass = sum"
"$GW" sweep sw.ini --out "$tmp/sw" --quiet 2>sw.err; rc=$?
if [ $rc -eq 0 ] && $PY - sw/results.csv "$r" <<'PY'; then
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
q = float(sys.argv[2])
sys.exit(0 if len(rows) == 2 and all(r["settling_warning"] == "1" and abs(float(r["settled_load_ratio"]) / q - 1) < 1e-5
                                      for r in rows) else 1)
PY
    ok "a sweep with clump-mass = sum over the union pile: rows settling_warning 1, q $r"
else
    ko "sweep over the union pile: exit $rc, $(head -c 300 sw.err)"
fi

test_summary test_settling_clumps
