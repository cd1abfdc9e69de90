#!/bin/bash
# test_hostile_fourteenth.sh GRANWAVE SRCDIR: the fourteenth hostile pass. Each
# numbered check failed on the binary before this pass (a1e9b0e); the guards
# (g) hold on both.
#  1 chain --gravity with a slow impact: the relative energy error was taken over
#    the initial kinetic energy alone, while gravity puts up to 1e8 times more
#    into motion (a column set on the wall at 1e-6 m/s). An error of 1e-8 of the
#    energy the run held read as 1 and the run stopped "blown up" (exit 1), with
#    the advice "lower dt (or dt-max), or use cvode" also under cvode; under
#    cvode at 1e-6 m/s the reported energy_error was 3.3e-3 and --energy-tol
#    stopped a run accurate to 3e-9. The error is now taken over the initial
#    energy plus the largest work gravity has done (the initial energy alone
#    without gravity, bit for bit).
#  2 dispersion --column-n runs the chain's collision under cvode (as its JSON
#    said) but checked --method, --rtol and --atol against the table's default
#    solver rk4: `--column-n 5 --rtol 1e-8` was refused as "has no effect with
#    the fixed-step rk4 solver" and `--method adams` as "not a method of solver
#    rk4" (exit 2, the program and Python alike); the JSON did not record the
#    method.
#  3 falcon --heights converted every height with g = 9.81 whatever --gravity
#    the column ran under (drop uses its own gravity for the same conversion):
#    --heights 5.1 --gravity 100 ran at 0.316 m/s, not sqrt(2 100 5.1e-3) =
#    1.01 m/s. The fall now uses the run's gravity when it has one, 9.81 when
#    it is off (the default), in the program and the library alike.
#  4 a layer sample whose UTF-8 byte-order mark stands alone on a blank or
#    comment line (the mark, then blank lines): the header was read from an
#    empty line and SIGSEGV (exit 139; found by fuzz_layer_sample). Refused as
#    "not a granwave layer sample" or "empty file" (exit 2), or read as
#    without the mark when a comment follows it.
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
PY=/usr/bin/python3
SRC=${2:-$(dirname "${BASH_SOURCE[0]}")/..}


# --- 1: the energy error under gravity
for s in cvode arkode rk4; do
    if runs_json "1: chain --n 3 --vimp 1e-6 --gravity 9.81 --solver $s" "$tmp/g_$s.json" \
        chain --n 3 --vimp 1e-6 --gravity 9.81 --solver $s; then
        e=$(jq_py "$tmp/g_$s.json" "d['energy_error']")
        [ "$(jq_py "$tmp/g_$s.json" "d['energy_error'] < 1e-5")" = True ] &&
            ok "1: chain --vimp 1e-6 --gravity 9.81 --solver $s: runs, energy_error $e" ||
            ko "1: chain --vimp 1e-6 --gravity 9.81 --solver $s: energy_error $e (>= 1e-5)"
    fi
done
# the slowest impact, under the adaptive solvers: it was stopped as blown up
for s in arkode cvode; do
    if runs_json "1: chain --n 3 --vimp 1e-9 --gravity 9.81 --solver $s" "$tmp/g9_$s.json" \
        chain --n 3 --vimp 1e-9 --gravity 9.81 --solver $s; then
        e=$(jq_py "$tmp/g9_$s.json" "d['energy_error']")
        [ "$(jq_py "$tmp/g9_$s.json" "d['energy_error'] < 1e-5")" = True ] && ! grep -q 'blew up' "$tmp/stderr" &&
            ok "1: chain --vimp 1e-9 --gravity 9.81 --solver $s: runs, energy_error $e" ||
            ko "1: chain --vimp 1e-9 --gravity 9.81 --solver $s: energy_error $e, $(cat "$tmp/stderr")"
    fi
done
# --energy-tol stopped an accurate run
runs_json "1: chain --vimp 1e-6 --gravity 9.81 --energy-tol 1e-6 runs (cvode)" "$tmp/gt.json" \
    chain --n 3 --vimp 1e-6 --gravity 9.81 --energy-tol 1e-6 &&
    ok "1: chain --vimp 1e-6 --gravity 9.81 --energy-tol 1e-6 runs (cvode)"
# g: a real blow-up is still one, with rk4's advice (an RK4 step 260 times a
# 30 um bead's, test_hostile_chain's case 27), with gravity too
for g in 0 9.81; do
    "$GW" chain --n 3 --radii 4e-3,3e-5,4e-3 --solver rk4 --dt 7e-8 --gravity $g >/dev/null 2>"$tmp/bl"; rc=$?
    [ $rc -eq 1 ] && grep -q 'blew up.*lower dt (or dt-max), or use cvode$' "$tmp/bl" &&
        ok "g: rk4 with a step 260 times the small bead's (gravity $g) still blows up, with rk4's advice" ||
        ko "g: rk4 blow-up, gravity $g: exit $rc ($(cat "$tmp/bl"))"
done

# --- 2: dispersion --column-n takes the chain's solver, cvode, by default
runs_json "2: dispersion --column-n 5" "$tmp/d0.json" dispersion --column-n 5
runs_json "2: dispersion --column-n 5 --solver cvode --method adams" "$tmp/da_given.json" \
    dispersion --column-n 5 --solver cvode --method adams
if runs_json "2: dispersion --column-n 5 --method adams" "$tmp/da.json" dispersion --column-n 5 --method adams; then
    [ "$(jq_py "$tmp/da.json" "(d['solver'], d['method'], d['settings']['method'])")" = "('cvode', 'adams', 'adams')" ] &&
        [ "$(jq_py "$tmp/da.json" "d['tau_n'] == json.load(open('$tmp/da_given.json'))['tau_n']")" = True ] &&
        [ "$(jq_py "$tmp/da.json" "d['tau_n'] != json.load(open('$tmp/d0.json'))['tau_n']")" = True ] &&
        ok "2: dispersion --column-n 5 --method adams runs cvode adams, as with --solver cvode, and records it" ||
        ko "2: --method adams: $(jq_py "$tmp/da.json" "(d['solver'], d.get('method'), d['tau_n'])")"
fi
if runs_json "2: dispersion --column-n 5 --rtol 1e-8" "$tmp/dr.json" dispersion --column-n 5 --rtol 1e-8; then
    [ "$(jq_py "$tmp/dr.json" "(d['solver'], d['rtol'])")" = "('cvode', 1e-08)" ] &&
        [ "$(jq_py "$tmp/dr.json" "d['tau_n'] != json.load(open('$tmp/d0.json'))['tau_n']")" = True ] &&
        ok "2: dispersion --column-n 5 --rtol 1e-8 runs cvode at 1e-8 (tau_N moves with it)" ||
        ko "2: --rtol 1e-8: $(jq_py "$tmp/dr.json" "(d['solver'], d['rtol'], d['tau_n'])")"
fi
[ -s "$tmp/d0.json" ] && [ "$(jq_py "$tmp/d0.json" "(d.get('method'), d['settings'].get('method'))")" = "('bdf', 'bdf')" ] &&
    ok "2: the column's JSON records its method (bdf)" ||
    ko "2: the column's JSON method: $(jq_py "$tmp/d0.json" "d.get('method')" 2>&1)"
pyenv $PY -c "
import json, granwave
r = granwave.dispersion(column_n=5, method='adams')
assert r['tau_n'] == json.load(open('$tmp/da.json'))['tau_n'], r['tau_n']
r = granwave.dispersion(column_n=5, rtol=1e-8)
assert r['rtol'] == 1e-8
" 2>"$tmp/pyerr" && ok "2: granwave.dispersion(column_n=5, method='adams' | rtol=1e-8) runs, the program's tau_N" ||
    ko "2: Python: $(tail -1 "$tmp/pyerr")"
# g: where the solver is rk4 (given, or the dispersion study itself) the
# tolerances and methods are still refused
refused "g: dispersion --column-n 5 --solver rk4 --rtol 1e-8" '^granwave dispersion --rtol: has no effect with the fixed-step rk4' \
    dispersion --column-n 5 --solver rk4 --rtol 1e-8
refused "g: dispersion --method adams (the study: rk4)" "^granwave dispersion --method: 'adams' is not a method of solver rk4" \
    dispersion --method adams
refused "2: dispersion --column-n 5 --method erk: named as not a method of cvode, the solver that runs" "^granwave dispersion --method: 'erk' is not a method of solver cvode" \
    dispersion --column-n 5 --method erk

# --- 3: falcon's heights fall in the run's gravity
for g in 0 100; do
    if runs_json "3: falcon --heights 5.1 --gravity $g" "$tmp/fh$g.json" falcon --n 1:2 --heights 5.1 --vimp 0.3 --gravity $g --quiet; then
        want=$($PY -c "import math; print(math.sqrt(2 * ($g if $g > 0 else 9.81) * 5.1e-3))")
        [ "$(jq_py "$tmp/fh$g.json" "abs(d['velocities'][1]['v_imp'] - $want) <= 1e-15 * $want")" = True ] &&
            ok "3: falcon --heights 5.1 --gravity $g runs at sqrt(2 g h) = $want m/s" ||
            ko "3: falcon --gravity $g: v_imp $(jq_py "$tmp/fh$g.json" "d['velocities'][1]['v_imp']") against $want"
    fi
done
pyenv $PY -c "
import json, granwave
r = granwave.falcon(n='1:2', vimp=[0.3], heights=[5.1], gravity=100)
assert r['v_imp'][1] == json.load(open('$tmp/fh100.json'))['velocities'][1]['v_imp'], r['v_imp']
" 2>"$tmp/pyerr" && ok "3: granwave.falcon(heights=[5.1], gravity=100): the program's speed" ||
    ko "3: Python: $(tail -1 "$tmp/pyerr")"

# --- 4: a byte-order mark alone on its line
printf '\xef\xbb\xbf\n\n\x8a\npor eno1.70d.\xdb' >"$tmp/bom1.txt"
printf '\xef\xbb\xbf\n\n' >"$tmp/bom2.txt"
refused "4: a sample of a byte-order mark, blank lines and junk" "^granwave layer-impact: sample '.*bom1.txt': line 3: not a granwave layer sample" \
    layer-impact --sample "$tmp/bom1.txt"
refused "4: a sample of a byte-order mark and blank lines" "^granwave layer-impact: sample '.*bom2.txt': empty file" \
    layer-impact --sample "$tmp/bom2.txt"
one='granwave-layer-sample 1\nwidth 20\nrm 0.325\nvolume_ratio 1\nn 1\n10 0.325 0.325\n'
printf "$one" >"$tmp/one.txt"
printf "\xef\xbb\xbf  # saved as UTF-8\n$one" >"$tmp/bom3.txt"
ia=(layer-impact --rb-rm 0.5 --vi 10 --gravity 0 --remove-walls --t-max 0.003)
if runs_json "4: the plain sample" "$tmp/i1.json" "${ia[@]}" --sample "$tmp/one.txt" &&
    runs_json "4: the mark before a comment line" "$tmp/i3.json" "${ia[@]}" --sample "$tmp/bom3.txt"; then
    [ "$(jq_py "$tmp/i3.json" "(d['e_n_first'], d['penetration']) == tuple(json.load(open('$tmp/i1.json'))[k] for k in ('e_n_first', 'penetration'))")" = True ] &&
        ok "4: a mark before a comment line reads as the sample without it" || ko "4: the mark changed the run"
fi

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
