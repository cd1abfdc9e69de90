#!/bin/bash
# test_chain_sampling_bounds.sh GRANWAVE SRCDIR: the default dt-out is tau_1/200
# of bead 1 on the wall; a wall far stiffer than the bead contacts makes that
# tiny against the column's own length, and every sample costs a fixed part
# (about 0.6 us) besides its O(n). The plan bounds the samples over the
# collision before the run (issue 18, unbounded work): more than 3e6 and more
# than 1e4 per bead transit is refused, naming dt-out and the interval that
# passes.
#   - chain --n 2 --k 1e3 --kwall 1e14 (dt-out 4.4 ns over a 28 ms collision,
#     6.4e6 samples, over a minute of CPU before) exits 2 at once with one line
#     naming --dt-out as the default, nothing written with --out; an explicit
#     --dt-out 5e-11 on 10 steel beads is refused naming the value;
#   - the suggested dt-out runs to its end (converged, 14.5 ms, 0.4 s), and
#     F_max and tau_N (events, not samples) are the same at twice that
#     interval to 1e-8 (tau_max not: bead 1's two wall contacts peak at the
#     same force to 1e-9, and either may hold the maximum);
#   - ordinary sampling still runs: the Falcon column (--n 40), a soft wall
#     under stiff beads, one bead at --dt-out 1e-10 (3.5e5 samples).
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"

REFUSE_TIMEOUT=5
refused "chain --n 2 --k 1e3 --kwall 1e14 (default dt-out)" \
    "^granwave chain --dt-out: the default tau_1/200 = 4.3[0-9]*e-09 s gives about 6.[0-9]*e\+06 samples over the collision .* raise dt-out to [0-9.e+-]+ s or more \(the wall's contact is far shorter" \
    chain --n 2 --k 1e3 --kwall 1e14 --out "$tmp/o"
refused "chain --n 10 --dt-out 5e-11" "^granwave chain --dt-out: 5e-11 s gives about .* per bead transit of 10 beads" \
    chain --n 10 --dt-out 5e-11 --out "$tmp/o"
printf '[sweep]\nmodel = chain\n[grid]\nvimp = 0.3\n[params]\nn = 2\nk = 1e3\nkwall = 1e14\n' >"$tmp/s.ini"
refused "a chain sweep's case with k = 1e3, kwall = 1e14 (before OUT is made)" \
    "^granwave sweep: .*s.ini: case 0: dt-out: the default" sweep "$tmp/s.ini" --out "$tmp/o"

# the suggested interval runs; the events do not depend on it
cpu_run 5 "$GW" chain --n 2 --k 1e3 --kwall 1e14 >/dev/null 2>"$tmp/e" </dev/null
lim=$(sed -n 's/.*raise dt-out to \([0-9.e+-]*\) s or more.*/\1/p' "$tmp/e")
if [ -z "$lim" ]; then ko "no suggested dt-out ($(head -c 300 "$tmp/e"))"
else
    lim2=$(/usr/bin/python3 -c "print(2 * $lim)")
    if runs_json "chain --n 2 --k 1e3 --kwall 1e14 --dt-out $lim" "$tmp/a.json" chain --n 2 --k 1e3 --kwall 1e14 --dt-out "$lim" &&
       runs_json "... --dt-out $lim2" "$tmp/b.json" chain --n 2 --k 1e3 --kwall 1e14 --dt-out "$lim2"; then
        r=$(/usr/bin/python3 -c "
import json
a, b = json.load(open('$tmp/a.json')), json.load(open('$tmp/b.json'))
print(max(abs(a[k] - b[k]) / abs(a[k]) for k in ('f_max', 'tau_n')), a['converged'] and a['n_maxima'] == b['n_maxima'])")
        [[ $r == *" True" ]] && /usr/bin/python3 -c "import sys; sys.exit(not float('${r% *}') < 1e-8)" &&
            ok "the suggested --dt-out $lim runs to its end; F_max, tau_N at twice it within ${r% *}" ||
            ko "the suggested --dt-out $lim: $r"
    fi
fi

# what the bound leaves alone
for a in "--n 40" "--n 2 --k 1e14 --kwall 1e3 --t-max 0.03" "--n 1 --dt-out 1e-10"; do
    # shellcheck disable=SC2086
    runs_json "chain $a" "$tmp/r.json" chain $a && ok "chain $a runs"
done

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
