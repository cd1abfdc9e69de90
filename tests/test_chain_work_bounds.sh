#!/bin/bash
# test_chain_work_bounds.sh GRANWAVE SRCDIR: a column whose light bead is held by
# heavy ones rings on its contacts all the time they hold it, and cvode and
# arkode follow every oscillation (about 260 steps each at rtol 1e-12, two
# restarts). The plan estimates that work before the run and refuses it above
# 2e7 bead-steps when the ringing is not the column's own (issue 18, unbounded
# work):
#   - chain --n 2 --radii 1e-3,1 (45 s of CPU, 17.1 million cvode steps before)
#     exits 2 at once (within 5 s) with one line naming --radii, the mass ratio,
#     the oscillations and the bound, and writes nothing with --out; the same
#     under arkode and in a chain sweep's case (before OUT is made);
#     Python's chain() refuses it naming radii;
#   - what the bound must leave alone still runs: rk4 on the same column (its
#     fixed step is bounded on its own), a bead 1e6 times lighter under a 0.1 m
#     one (407 oscillations per transit, 1.1e6 bead-steps) and the documented
#     polydisperse columns.
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

# --- refused before the run (the old code ran them for 35-60 s: killed at 5 s)
REFUSE_TIMEOUT=5
refused "chain --radii 1e-3,1 (cvode)" \
    "^granwave chain --radii: bead 1 \(3.29e-05 kg\) is 1e\+09 times lighter than bead 2 .* about 6.4[0-9]e\+04 oscillations over the collision .* above the bound 2e\+07" \
    chain --n 2 --radii 1e-3,1 --out "$tmp/o"
refused "chain --radii 1e-3,1 --solver arkode" "^granwave chain --radii: .* bead-steps of arkode" \
    chain --n 2 --radii 1e-3,1 --solver arkode --out "$tmp/o"
refused "chain --radii 1e-3,1e-3,1 (a light bead between the wall and a heavy one)" \
    "^granwave chain --radii: bead [12] .* times lighter than bead 3 " chain --n 3 --radii 1e-3,1e-3,1 --out "$tmp/o"
printf '[sweep]\nmodel = chain\n[grid]\nvimp = 0.1, 0.3\n[params]\nn = 2\nradii = 1e-3, 1\n' >"$tmp/s.ini"
refused "a chain sweep's case with radii 1e-3, 1 (before OUT is made)" \
    "^granwave sweep: .*s.ini: case 0: radii: bead 1 .* above the bound 2e\+07" sweep "$tmp/s.ini" --out "$tmp/o"

# Python: the same check in the library, named by keyword
if out=$(pyenv cpu_run 20 $PY -c "
import granwave
try:
    granwave.chain(n=2, radii=[1e-3, 1.0])
except granwave.GranwaveValueError as e:
    print(e)
else:
    print('ran')
" 2>&1) && [[ $out == "chain: radii: bead 1 "*"above the bound 2e+07"* ]]; then
    ok "Python chain(radii=[1e-3, 1.0]) refused: ${out:0:120}"
else ko "Python chain(radii=[1e-3, 1.0]): ${out:0:300}"; fi

# --- what the bound leaves alone
if runs_json "rk4 on --radii 1e-3,1" "$tmp/rk4.json" chain --n 2 --radii 1e-3,1 --solver rk4; then
    r=$(jq_py "$tmp/rk4.json" "'%d %.3g' % (d['converged'], d['energy_error'])")
    [[ $r == "1 "* ]] && ok "rk4 on --radii 1e-3,1 runs to its end (converged, energy error ${r#* })" ||
        ko "rk4 on --radii 1e-3,1: $r"
fi
if runs_json "--radii 1e-3,1e-1 (cvode)" "$tmp/r100.json" chain --n 2 --radii 1e-3,1e-1; then
    n=$(jq_py "$tmp/r100.json" "d['n_maxima']")
    # the run the estimate is measured on: about 260 steps an oscillation
    [ "$n" -gt 500 ] && ok "--radii 1e-3,1e-1 runs: $n wall-force maxima (the light bead rings), $(jq_py "$tmp/r100.json" "d['steps']") steps" ||
        ko "--radii 1e-3,1e-1: only $n maxima"
fi
for a in "--n 2 --radii 5e-4,1e-2" "--n 2 --radii 2e-4,1e-2" "--n 3 --radii 4e-3,3e-5,4e-3" \
         "--n 3 --radii 2e-3,4e-3,8e-3" "--n 2 --radii 1,1e-3" "--n 2 --k 1e14 --kwall 1e3 --t-max 0.03"; do
    # shellcheck disable=SC2086
    runs_json "chain $a" "$tmp/r.json" chain $a && ok "chain $a runs"
done

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
