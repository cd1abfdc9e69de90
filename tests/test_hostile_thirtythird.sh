#!/bin/bash
# test_hostile_thirtythird.sh GRANWAVE SRCDIR: what the thirty-third hostile
# pass found, fixed at its root and asserted here.
#  1 A block over no particle was found by the run only. layer-impact lowers
#    the block onto the first particle under it; on a sparse sample an
#    abscissa over none failed in gw_layer_impact itself ("granwave
#    layer-impact: x: ...", not --x), so `sweep --check` said valid, and the
#    sweep ran and journaled the cases before it, then exited 2. Now in
#    gw_layer_impact_check: the command names --x, the check pass refuses,
#    nothing is written.
#  2 A --height-rm that holds no particle froze all of them: the block hit a
#    rigid bed with exit 0 (--height-rm 1 on the 40-disc pile: 0 mobile, e_n
#    0.965 against 0.153 on the pile). Refused now naming --height-rm and the
#    least height that leaves a particle mobile, as the other side (a layer
#    below every centre) was.
#  3 A clump with one frozen member is frozen whole (layer_clumps.c), but
#    n_mobile and n_frozen counted each disc by its own centre: 21 mobile of
#    42 said where one clump of 2 discs moved, and 0 clumps mobile at
#    --height-rm 2 ran. The counts are now of what moves, and a layer holding
#    no clump whole is refused as in 2.
#  4 dispersion --amp far below 1e-3: the perturbation amp d0 on overlaps of
#    d0 nears d0's rounding (2.2e-16 d0); at 1e-16 the ridge came out 12 % off
#    and omega_c 2 % (n 1024), exit 0 without a word. Refused below 1e-12.
#  5 Two impact velocities one rounding apart: wavespeed --vimp
#    0.3,0.30000000000000004 fitted beta -278424 and C3 0 over their
#    difference (exit 0); the check of speeds given twice took only equal
#    ones. Two speeds within a relative 1e-6 are now refused alike (falcon's
#    heights too).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 a block over no particle: refused before the run, also by a sweep's check ---
# two discs at the left of a 20 m box: the block at the centre meets nothing
printf 'granwave-layer-sample 1\nwidth 20\nrm 0.325\nn 2\n0.325 0.325 0.325\n0.975 0.325 0.325\n' >sparse.txt
refused "layer-impact over no particle: refused naming --x" \
    "^granwave layer-impact --x: no soil particle lies under the block" \
    layer-impact --sample sparse.txt --x 0 --out o
printf '[sweep]\nmodel = layer\n[grid]\nx = -9.35, 0\n[params]\nsample = sparse.txt\nvi = 5\n' >nx.ini
refused "sweep --check over a case whose block meets no particle: refused" \
    "^granwave sweep: nx.ini: case 1: x: no soil particle lies under the block" \
    sweep nx.ini --out o --check
refused "sweep over a case whose block meets no particle: refused before any case ran (no journal)" \
    "^granwave sweep: nx.ini: case 1: x: no soil particle" \
    sweep nx.ini --out o --quiet
# the case that meets a particle still runs
if runs_json "layer-impact on the sparse sample's first disc" sp.json layer-impact --sample sparse.txt --x -9.35 --vi 5; then
    v=$(jq_py sp.json "d['n_mobile'] == 2 and d['v_ni'] == 5")
    [ "$v" = True ] && ok "the block over a particle of the sparse sample runs" || ko "sparse sample, x -9.35: $v"
fi

# --- 2, 3 a mobile layer that holds no particle, no clump whole ---
"$GW" layer-make --n 40 --seed 1 --out discs.txt >/dev/null 2>&1 &&
    "$GW" layer-make --n 12 --clumps --seed 2 --out clumps.txt >/dev/null 2>&1 ||
    ko "layer-make of the two samples failed"
# the least height that leaves a body mobile, computed here from the file:
# a body (a disc, or a clump: its discs sharing an id) moves when its lowest
# centre lies at or above the surface (max y + r) less H R_m
least() {
    /usr/bin/python3 -c "
import sys
L = open('$1').read().split('\n')
rm = float([l.split()[1] for l in L if l.startswith('rm ')][0])
k = [i for i, l in enumerate(L) if l.startswith('n ')][0]
P = [list(map(float, l.split())) for l in L[k + 1:k + 1 + int(L[k].split()[1])]]
top = max(p[1] + p[2] for p in P)
lo = {}
for i, p in enumerate(P):
    b = int(p[3]) if len(p) > 3 else i
    lo[b] = min(lo.get(b, 1e300), p[1])
print('%.6f' % ((top - max(lo.values())) / rm))"
}
# the clump sample's discs in clumps wholly at or above the surface less H R_m
mobile_discs() {
    /usr/bin/python3 -c "
L = open('$1').read().split('\n')
rm = float([l.split()[1] for l in L if l.startswith('rm ')][0])
k = [i for i, l in enumerate(L) if l.startswith('n ')][0]
P = [list(map(float, l.split())) for l in L[k + 1:k + 1 + int(L[k].split()[1])]]
yf = max(p[1] + p[2] for p in P) - $2 * rm
frozen = {int(p[3]) for p in P if p[1] < yf}
print(sum(1 for p in P if int(p[3]) not in frozen))"
}
hd=$(least discs.txt) hc=$(least clumps.txt)
below_d=$(/usr/bin/python3 -c "print($hd * 0.99)") below_c=$(/usr/bin/python3 -c "print($hc * 0.99)")
refused "layer-impact --height-rm $below_d on the disc pile (no centre within it): refused naming --height-rm" \
    "^granwave layer-impact --height-rm: a mobile layer of .* R_m holds no particle's centre: every particle is frozen .*give at least" \
    layer-impact --sample discs.txt --height-rm "$below_d" --out o
refused "layer-impact --height-rm $below_c on the clump pile (no clump whole within it): refused naming --height-rm" \
    "^granwave layer-impact --height-rm: a mobile layer of .* R_m holds no clump whole" \
    layer-impact --sample clumps.txt --height-rm "$below_c" --out o
# the least height the message gives runs, with a particle mobile
at=$(cpu_run 20 "$GW" layer-impact --sample clumps.txt --height-rm "$below_c" 2>&1 | sed -n 's/.*give at least \([0-9.e+-]*\),.*/\1/p')
if [ -n "$at" ] && runs_json "layer-impact --height-rm $at (the least the message gives)" at.json \
    layer-impact --sample clumps.txt --height-rm "$at"; then
    v=$(jq_py at.json "d['n_mobile'] > 0 and d['n_mobile'] + d['n_frozen'] == 42")
    [ "$v" = True ] && ok "the height the refusal gives ($at, least $hc) runs with a clump mobile" ||
        ko "--height-rm $at: $(head -c 200 at.json)"
else
    ko "the refusal gave no height ($at)"
fi
# the counts are of what moves: a clump with a frozen member is frozen whole
h=$(/usr/bin/python3 -c "print($hc + 0.3)")
want=$(mobile_discs clumps.txt "$h")
if runs_json "layer-impact --height-rm $h on the clump pile" c.json layer-impact --sample clumps.txt --height-rm "$h"; then
    v=$(jq_py c.json "d['n_mobile'] == $want and d['n_frozen'] == 42 - $want")
    [ "$v" = True ] && ok "clump pile at --height-rm $h: n_mobile $want, the discs of clumps wholly in the layer" ||
        ko "clump pile --height-rm $h: n_mobile $(jq_py c.json "d['n_mobile']"), expected $want"
fi
py_checks <<EOF
import granwave
try:
    granwave.layer_impact(sample="discs.txt", height_rm=$below_d)
    print("FAIL: Python layer_impact height_rm=$below_d ran on a frozen bed")
except granwave.GranwaveValueError as e:
    print(("PASS: " if "height_rm" in str(e) else "FAIL: ") + "Python layer_impact: a layer holding no particle "
          "raises GranwaveValueError naming height_rm (%s)" % str(e)[:80])
EOF

# --- 4 dispersion's perturbation above the overlap's rounding ---
refused "dispersion --amp 1e-16: refused naming --amp" "^granwave dispersion --amp: 1e-16 is outside \[1e-12, 0.1\]" \
    dispersion --n 16 --t-samples 64 --amp 1e-16 --out o
if runs_json "dispersion --amp 1e-12" a12.json dispersion --n 16 --t-samples 64 --amp 1e-12 &&
    runs_json "dispersion --amp 1e-3" a3.json dispersion --n 16 --t-samples 64; then
    v=$(/usr/bin/python3 -c "
import json
a, b = json.load(open('a12.json')), json.load(open('a3.json'))
print(a['n_resolved'] == b['n_resolved'] and abs(a['omega_c_measured'] / b['omega_c_measured'] - 1) < 1e-4)")
    [ "$v" = True ] && ok "dispersion --amp 1e-12 (the bound): its ridge 1e-3's within 1e-4" ||
        ko "dispersion --amp 1e-12: $(head -c 300 a12.json)"
fi
py_checks <<'EOF'
import granwave
try:
    granwave.dispersion(n=16, t_samples=64, amp=1e-16)
    print("FAIL: Python dispersion amp=1e-16 ran")
except granwave.GranwaveValueError as e:
    print(("PASS: " if "amp" in str(e) else "FAIL: ") + "Python dispersion amp=1e-16: GranwaveValueError naming amp")
EOF

# --- 5 two impact velocities within a relative 1e-6 ---
refused "wavespeed --vimp 0.3,0.30000000000000004: refused naming both items" \
    "^granwave wavespeed --vimp: item 2 gives the impact velocity 0.30000000000000004 m/s, within a relative .* of item 1" \
    wavespeed --n 6:8 --vimp 0.3,0.30000000000000004 --out o
refused "wavespeed --vimp 0.3,0.5,0.3000001: refused naming items 3 and 1" \
    "^granwave wavespeed --vimp: item 3 gives .* of item 1 " \
    wavespeed --n 6:8 --vimp 0.3,0.5,0.3000001 --out o
refused "falcon --vimp sqrt(2 g h) to 14 digits --heights h: refused naming the height and the speed" \
    "^granwave falcon --heights: item 1 gives the impact velocity .* of item 1 of vimp" \
    falcon --n 1:2 --vimp 0.19809088823063 --heights 2 --out o
# speeds a relative 2e-6 apart still run, their exponent within 1e-3 of the
# one over speeds far apart
if runs_json "wavespeed --vimp 0.3,0.3000006" w1.json wavespeed --n 6:8 --vimp 0.3,0.3000006 --quiet &&
    runs_json "wavespeed --vimp 0.3,0.5" w2.json wavespeed --n 6:8 --vimp 0.3,0.5 --quiet; then
    v=$(/usr/bin/python3 -c "
import json
a, b = json.load(open('w1.json')), json.load(open('w2.json'))
print(abs(a['beta'] - b['beta']) < 1e-3)")
    [ "$v" = True ] && ok "wavespeed over speeds 2e-6 apart: beta within 1e-3 of the one over 0.3 and 0.5" ||
        ko "wavespeed --vimp 0.3,0.3000006: beta $(jq_py w1.json "d['beta']")"
fi
py_checks <<'EOF'
import granwave
try:
    granwave.wavespeed(n=(6, 8), vimp=[0.3, 0.30000000000000004])
    print("FAIL: Python wavespeed over 0.3 and its next double ran")
except granwave.GranwaveValueError as e:
    print(("PASS: " if "vimp" in str(e) else "FAIL: ") + "Python wavespeed: speeds one rounding apart raise "
          "GranwaveValueError naming vimp")
EOF

test_summary test_hostile_thirtythird
