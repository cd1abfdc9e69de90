#!/bin/bash
# test_chain_cli.sh GRANWAVE SRCDIR: the program's interface for the chain
# commands. Bad input must exit with code 2 and print exactly one line on stderr
# naming the input, write nothing to stdout and create no output directory;
# good input must print JSON with the documented keys.
set -u
GW=$1
PY=/usr/bin/python3
fails=0; passes=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

bad1() { # expected-word args...
    local word=$1; shift
    "$GW" "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
    local lines; lines=$(wc -l <"$tmp/err")
    if [ $rc -eq 2 ] && [ "$lines" -eq 1 ] && grep -q -- "$word" "$tmp/err" && [ ! -s "$tmp/out" ] && [ ! -e "$tmp/never" ]; then
        echo "PASS: bad input '$*' -> exit 2: $(cat "$tmp/err")"; passes=$((passes+1))
    else
        echo "FAIL: bad input '$*' -> exit $rc, $lines stderr line(s): $(cat "$tmp/err") stdout: $(head -c 200 "$tmp/out") out dir created: $([ -e "$tmp/never" ] && echo yes || echo no)"; fails=$((fails+1))
    fi
    rm -rf "$tmp/never"
}

# every case also asks for an output directory, which must not appear
bad() { bad1 "$1" "${@:2}" --out "$tmp/never"; }
bad "n" chain --n 0
bad "n" chain --n -3
bad "n" chain --n 2.5
bad "vimp" chain --vimp 0
bad "vimp" chain --vimp -0.3
bad "vimp" chain --vimp nan
bad "k" chain --k -1
bad "k" chain --k nan
bad "kwall" chain --kwall inf
bad "kwall" chain --kwall 0
bad "mass" chain --mass 0
bad "solver" chain --solver euler
bad "method" chain --method gear
bad "method" chain --solver rk4 --method bdf
bad "bogus" chain --bogus
bad "material" chain --material unobtainium
bad "damping" chain --damping viscous
bad "rtol" chain --rtol 2
bad1 "needs a value" chain --n
bad "n" chain --n 99999999999999999999
bad "unexpected" chain extra
bad "falcon --n" falcon --n 5:2
bad "falcon --vimp" falcon --vimp 0.3,abc
bad "heights" falcon --heights -1
bad "unknown command" nosuchcommand
bad "radii" chain --n 3 --radii 4e-3,3e-3
bad "radii" chain --n 2 --radii 4e-3,-1
bad "radii" falcon --radii 4e-3
bad "accuracy" falcon --accuracy 1e-7 --solver cvode
bad "accuracy" falcon --accuracy 1e-12
bad "sheet" chain --sheet foam
bad "sheet" chain --sheet brass --kwall 1e9
bad "restitution" chain --restitution 0.9
bad "restitution" chain --damping hc --restitution 1.5

check() { # description, command (status 0 expected)
    local what=$1; shift
    if "$@"; then echo "PASS: $what"; passes=$((passes+1)); else echo "FAIL: $what"; fails=$((fails+1)); fi
}

check "chain --help exits 0 and documents --kwall" bash -c "'$GW' chain --help | grep -q -- '--kwall'"
check "falcon --help exits 0" bash -c "'$GW' falcon --help >/dev/null"
"$GW" chain --n 7 --vimp 0.3 --solver cvode --json >"$tmp/c.json"
check "chain --json has the documented keys" $PY - "$tmp/c.json" <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
keys = "n v_imp solver f_max tau_max tau_n period energy_error final_velocities detach_times n_s e_rel_over_e_k eps_eff steps rhs_evals".split()
missing = [k for k in keys if k not in d]
assert not missing, missing
assert d["n"] == 7 and len(d["final_velocities"]) == 7 and len(d["detach_times"]) == 7
assert d["final_velocities"][-1] < 0, "top bead must move away (negative)"
assert 60 < d["f_max"] < 75 and d["energy_error"] < 1e-8
PYEOF
check "chain --out writes CSV with a version header" bash -c "'$GW' chain --n 5 --out '$tmp/o' >/dev/null && head -1 '$tmp/o/chain_wall_force.csv' | grep -q 'granwave' && grep -q '^t_s,f_wall_N' '$tmp/o/chain_wall_force.csv' && test -s '$tmp/o/chain_beads.csv' && test -s '$tmp/o/chain.json'"
check "falcon small run writes report and tables" bash -c "'$GW' falcon --n 1:8 --heights 5.1 --quiet --out '$tmp/f' >/dev/null && test -s '$tmp/f/report.md' && test -s '$tmp/f/falcon_runs.csv' && test -s '$tmp/f/falcon_summary.json' && test -s '$tmp/f/trace_n7_beads.csv'"
check "solver failure: exit 1, backend message with the time, state kept" bash -c "'$GW' chain --n 40 --max-steps 30 --out '$tmp/fail' 2>'$tmp/ferr'; test \$? -eq 1 && grep -q 'failed at t = ' '$tmp/ferr' && grep -q 'mxstep' '$tmp/ferr' && test -s '$tmp/fail/chain_failure.json' && test -s '$tmp/fail/chain_wall_force.csv'"
check "energy monitor: exit 1 naming the limit" bash -c "'$GW' chain --n 10 --energy-tol 1e-14 2>'$tmp/eerr'; test \$? -eq 1 && grep -q 'exceeds the limit' '$tmp/eerr'"
check "no temporary files left behind" bash -c "! ls '$tmp'/o '$tmp'/f | grep -q '\.tmp'"

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
