#!/bin/bash
# test_layer_make_rest.sh GRANWAVE SRCDIR: layer-make calls a pile settled only
# when it is at rest, so that layer-impact takes every sample marked
# 'converged 1'. The kinetic energy alone was judged, once per 0.01 s: a pile
# still swinging on its contacts has a small E_k at its turning points.
# `layer-make --n 1` was called settled with its floor carrying 26.2 times the
# disc's weight and `--n 5 --width-rm 50` with 1.55 times; layer-impact refused
# both samples (more than 1.5 times the weight: strain energy the impact would
# release), and `--n 12 --clumps --aspect-max 1` at 0.31 s with nothing
# touching (max overlap 0: the pile in the air). With only that bound added, the single disc was next caught at the
# top of a bounce, 3 mm above the floor. Now settled needs E_k plus the energy
# the grains in flight (touching nothing) will land with, m g times their drop,
# below the threshold (1e-5 M g R_m), and the floor carrying at most 1.5 times
# the weight. Checks, for each pile:
#  1 a sample marked converged 1 in its header has the JSON's converged true
#    and floor_load at most 1.5;
#  2 the sample's own geometry, read by this script: E_k plus m g times the
#    straight drop of each disc that touches neither the floor, a side wall
#    nor another disc is below 1e-5 M g R_m (disc masses pi r^2 2650 kg/m^3);
#  3 layer-impact takes it: the rest check passes (exit 0) for an impact on
#    its first disc;
#  4 a pile not settled by t-max (--t-max 0.3) is written with converged 0,
#    its JSON converged false, and one warning line.
set -u
GW=$1
SRC=${2:-}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"

json() { /usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get(sys.argv[2]))' "$1" "$2"; }

# E_k (J, $2) plus the energy the discs that touch nothing (floor, walls, another
# disc) gain falling straight down until they touch, over 1e-5 M g R_m, from the
# sample's lines
fall_over_threshold() {
    /usr/bin/python3 - "$2" <(sample_discs "$1") <<'EOF'
import math, sys
head, *body = open(sys.argv[2]).read().splitlines()
width, rm = float(head.split()[0]), float(head.split()[1])
rows = [tuple(map(float, line.split())) for line in body]
g, mass = 9.81, lambda r: math.pi * r * r * 2650
fall = float(sys.argv[1])
for i, (x, y, r) in enumerate(rows):
    touch = y < r or x < r or width - x < r
    for j, (u, v, s) in enumerate(rows):
        if j != i and math.hypot(u - x, v - y) < r + s:
            touch = True
    if not touch:
        drop = y - r
        for j, (u, v, s) in enumerate(rows):
            if j != i and abs(u - x) < r + s and v < y:
                drop = min(drop, y - v - math.sqrt((r + s) ** 2 - (u - x) ** 2))
        fall += mass(r) * g * max(drop, 0)
print(fall / (1e-5 * sum(mass(r) for _, _, r in rows) * g * rm))
EOF
}

pile() { # WHAT, then layer-make options
    local what=$1; shift
    if ! "$GW" layer-make "$@" --out "$tmp/s.txt" --json >"$tmp/s.json" 2>"$tmp/s.err"; then
        ko "$what: layer-make failed: $(head -c 300 "$tmp/s.err")"; return
    fi
    local conv load
    conv=$(json "$tmp/s.json" converged) load=$(json "$tmp/s.json" floor_load)
    if grep -q "^# settled: .*converged 1, .*floor load" "$tmp/s.txt" && [ "$conv" = True ] &&
        /usr/bin/python3 -c 'import sys; sys.exit(not 0 < float(sys.argv[1]) <= 1.5)' "$load"; then
        ok "$what: converged 1, floor load $load of the weight"
    else
        ko "$what: converged $conv, floor load $load ($(grep '^# settled' "$tmp/s.txt" | head -c 200))"
    fi
    local q
    q=$(fall_over_threshold "$tmp/s.txt" "$(json "$tmp/s.json" ke_final)")
    if /usr/bin/python3 -c 'import sys; sys.exit(not float(sys.argv[1]) < 1)' "$q"; then
        ok "$what: E_k and the fall of the grains in flight: $q of the threshold"
    else
        ko "$what: E_k and the fall of the grains in flight: $q of the threshold"
    fi
    # an impact on the first disc (x from the box centre), run for one step
    local x
    x=$(sample_discs "$tmp/s.txt" | awk 'NR == 1 { w = $1 } NR == 2 { printf "%.17g\n", $1 - w / 2; exit }')
    if "$GW" layer-impact --sample "$tmp/s.txt" --x "$x" --t-max 1e-5 --json >"$tmp/i.json" 2>"$tmp/i.err"; then
        ok "$what: layer-impact takes the sample"
    else
        ko "$what: layer-impact refused it: $(head -c 300 "$tmp/i.err")"
    fi
}
pile "one disc" --n 1
pile "five discs in a 50 R_m box" --n 5 --width-rm 50
pile "12 discs" --n 12 --width-rm 6
# one-disc clumps (settled by the clump code): called settled at 0.31 s with
# no contact at all (max overlap 0), the pile still in the air
pile "12 one-disc clumps" --n 12 --clumps --aspect-max 1

# 4: not settled by t-max
if "$GW" layer-make --n 5 --width-rm 50 --t-max 0.3 --out "$tmp/u.txt" --quiet --json >"$tmp/u.json" 2>"$tmp/u.err" &&
    grep -q "^# settled: .*converged 0" "$tmp/u.txt" && [ "$(json "$tmp/u.json" converged)" = False ] &&
    [ "$(wc -l <"$tmp/u.err")" -eq 1 ] && grep -q "did not settle" "$tmp/u.err"; then
    ok "a pile not settled by t-max: converged 0, one warning line"
else
    ko "a pile not settled by t-max: $(head -c 300 "$tmp/u.err")"
fi

echo "test_layer_make_rest: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
