#!/bin/bash
# test_chain_located_outcomes.sh GRANWAVE SRCDIR: what the twenty-eighth hostile
# pass found in the column's single run, each fixed at its root:
#  1 A grazing re-contact's detach time moved with the sampling: --n 5 --kwall
#    1e4, beads 1 and 2 touch again by 0.7 nm as the wall opens and part at
#    0.0168764 s; bead 1's detach time was that at the default sampling but the
#    wall's 0.0166364 s at --dt-out 1e-8, 3e-8, 1e-7, 2e-7 (the run stopped at
#    the first sample after the pair stopped acting, before its opening's
#    root). The run now goes on to the located opening. Tolerance 1e-6 s: a
#    grazing contact opens when its overlap reaches zero, known to the states'
#    error over the pair's speed; cvode, arkode and rk4 at seven samplings
#    spread over 8.2e-8 s, the fault is 2.4e-4 s.
#  2 A column held on the wall by gravity (--n 2 --gravity 1e3 --vimp 0.01)
#    reported the values its own warning calls undecided as numbers (eps_eff
#    -0.0058 by default, -0.467 at --dt-out 7e-6): F_max, tau_max, tau_N, the
#    final velocities, eps_eff and eps_col are now null in JSON, n/a in the
#    text, nan in Python, at every sampling; a column that leaves keeps them.
#  3 A --dt above the step the run takes (the automatic dt-max; rk4's dt-out,
#    where its steps end) ran at that step byte for byte while the settings
#    recorded the dt given. It still runs (exit 0, the same results) with one
#    warning line naming --dt and the step, and the settings' dt is the step
#    taken, dt_given the one given (JSON, the --out files' header, Python);
#    drop the same.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

# --- 1: detach times across samplings and solvers ---
runs_json "1 default sampling" d0.json chain --n 5 --kwall 1e4 || true
ref=$(jq_py d0.json "repr(d['detach_times'])")
i=0
for a in "--dt-out 1e-8" "--dt-out 3e-8" "--dt-out 1e-7" "--dt-out 2e-7" "--dt-out 5e-7" "--dt-out 1e-5" \
         "--solver arkode" "--solver rk4" "--solver rk4 --dt-out 1e-7"; do
    i=$((i + 1))
    # shellcheck disable=SC2086
    if runs_json "1 $a" "d$i.json" chain --n 5 --kwall 1e4 $a; then
        v=$(jq_py "d$i.json" "max(abs(a - b) for a, b in zip(d['detach_times'], $ref))")
        if /usr/bin/python3 -c "import sys; sys.exit(0 if $v <= 1e-6 else 1)"; then
            ok "1 detach times at $a within 1e-6 s of the default's (largest difference $v s)"
        else
            ko "1 detach times at $a differ from the default's by $v s ($(jq_py "d$i.json" "d['detach_times']") vs $ref)"
        fi
        [ "$(jq_py "d$i.json" "d['wall_contacts']")" = "$(jq_py d0.json "d['wall_contacts']")" ] &&
            ok "1 wall contacts at $a as the default's" || ko "1 wall contacts at $a differ"
    fi
done

# --- 2: a held column's undecided values ---
for a in "" "--dt-out 7e-6" "--dt-out 1e-6" "--solver rk4"; do
    # shellcheck disable=SC2086
    if runs_json "2 held $a" h.json chain --n 2 --gravity 1e3 --vimp 0.01 $a; then
        r=$(jq_py h.json "d['wall_pending'].startswith('held by gravity') and all(d[k] is None for k in ('f_max', 'tau_max', 'tau_n', 'eps_eff', 'eps_col')) and all(v is None for v in d['final_velocities'])")
        [ "$r" = True ] && ok "2 held ${a:-default}: undecided values null" ||
            ko "2 held ${a:-default}: $(jq_py h.json "[d[k] for k in ('wall_pending', 'f_max', 'tau_n', 'eps_eff', 'eps_col', 'final_velocities')]")"
        grep -q "gravity holds the column" "$tmp/stderr" && ok "2 held ${a:-default}: the warning" ||
            ko "2 held ${a:-default}: no warning ($(cat "$tmp/stderr"))"
    fi
done
"$GW" chain --n 2 --gravity 1e3 --vimp 0.01 >t.txt 2>/dev/null
grep -qE '^  eps_eff +n/a +eps_col n/a' t.txt && grep -qE '^  F_max +n/a N' t.txt &&
    ok "2 held: n/a in the text" || ko "2 held text: $(grep -E 'eps_eff|F_max' t.txt)"
if runs_json "2 leaving" l.json chain --n 2; then
    [ "$(jq_py l.json "all(isinstance(d[k], float) for k in ('f_max', 'tau_n', 'eps_eff', 'eps_col'))")" = True ] &&
        ok "2 a column that leaves keeps its numbers" || ko "2 leaving column: $(jq_py l.json "d['eps_eff']")"
fi

# --- 3: --dt above the step taken ---
runs_json "3 dt-max" m.json chain --n 3 || true
dtmax=$(jq_py m.json "repr(d['settings']['solver']['dt_max'])")
# (--quiet: no progress display, which a run past 2 s of the clock shows on a
# loaded machine; the warnings stay)
if runs_json "3 --dt 1e-3" a.json chain --n 3 --dt 1e-3 --quiet; then
    [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && grep -qE -- "--dt 0.001 s is above dt-max = " "$tmp/stderr" &&
        ok "3 --dt 1e-3: one warning line naming --dt and dt-max" || ko "3 --dt 1e-3 stderr: $(cat "$tmp/stderr")"
    [ "$(jq_py a.json "(d['settings']['solver']['dt'], d['settings']['solver']['dt_given'])")" = "($dtmax, 0.001)" ] &&
        ok "3 --dt 1e-3: settings dt the step taken, dt_given 1e-3" ||
        ko "3 --dt 1e-3 settings: $(jq_py a.json "d['settings']['solver']")"
    runs_json "3 --dt dt-max" b.json chain --n 3 --dt "$dtmax" --quiet &&
        [ "$(jq_py a.json "(d['f_max'], d['final_velocities'], d['steps'])")" = "$(jq_py b.json "(d['f_max'], d['final_velocities'], d['steps'])")" ] &&
        ok "3 --dt 1e-3: the results of --dt dt-max" || ko "3 --dt 1e-3 results differ from --dt dt-max's"
    [ -s "$tmp/stderr" ] && ko "3 --dt dt-max warned: $(cat "$tmp/stderr")" || ok "3 --dt dt-max: no warning"
fi
if runs_json "3 rk4 --dt 1e-3 --dt-out 1e-6" c.json chain --n 3 --solver rk4 --dt 1e-3 --dt-out 1e-6; then
    grep -qE -- "--dt 0.001 s is above --dt-out = 1e-06 s" "$tmp/stderr" &&
        ok "3 rk4: the warning names --dt-out" || ko "3 rk4 stderr: $(cat "$tmp/stderr")"
    [ "$(jq_py c.json "d['settings']['solver']['dt']")" = 1e-06 ] && ok "3 rk4: settings dt 1e-6" ||
        ko "3 rk4 settings dt $(jq_py c.json "d['settings']['solver']['dt']")"
    runs_json "3 rk4 --dt 1e-6" e.json chain --n 3 --solver rk4 --dt 1e-6 --dt-out 1e-6 &&
        [ "$(jq_py c.json "(d['f_max'], d['final_velocities'])")" = "$(jq_py e.json "(d['f_max'], d['final_velocities'])")" ] &&
        ok "3 rk4: the results of --dt 1e-6" || ko "3 rk4 results differ"
fi
# the drop: its own step (cvode's first, capped at its dt-max) the same way
if runs_json "3 drop --dt 1e-3" da.json drop --n 3 --dt 1e-3; then
    grep -qE -- "--dt 0.001 s is above dt-max = " "$tmp/stderr" && ok "3 drop --dt 1e-3: the warning" ||
        ko "3 drop stderr: $(cat "$tmp/stderr")"
    ddt=$(jq_py da.json "repr(d['settings']['solver']['dt_max'])")
    [ "$(jq_py da.json "(d['settings']['solver']['dt'], d['settings']['solver']['dt_given'])")" = "($ddt, 0.001)" ] &&
        ok "3 drop: settings dt the step taken, dt_given 1e-3" || ko "3 drop settings: $(jq_py da.json "d['settings']['solver']")"
    runs_json "3 drop --dt dt-max" db.json drop --n 3 --dt "$ddt" &&
        [ "$(jq_py da.json "d['f_max']")" = "$(jq_py db.json "d['f_max']")" ] &&
        ok "3 drop --dt 1e-3: the results of --dt dt-max" || ko "3 drop results differ from --dt dt-max's"
fi
rm -rf o
if "$GW" chain --n 3 --dt 1e-3 --out o >/dev/null 2>&1; then
    /usr/bin/python3 -c "
import json
line = next(l for l in open('o/chain_wall_force.csv') if l.startswith('# settings: '))
s = json.loads(line[len('# settings: '):])['solver']
raise SystemExit(0 if s['dt'] == $dtmax and s['dt_given'] == 1e-3 else 1)" &&
        ok "3 the --out header records the step taken" || ko "3 --out header: $(grep '# settings' o/chain_wall_force.csv)"
else
    ko "3 --out run failed"
fi

py_checks <<EOF
import math, warnings
import granwave
def check(what, cond):
    print(("PASS: " if cond else "FAIL: ") + what)
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = granwave.chain(n=2, gravity=1e3, vimp=0.01)
check("2 Python held: f_max, tau_max, tau_n, eps_eff, eps_col nan",
      all(math.isnan(r[k]) for k in ("f_max", "tau_max", "tau_n", "eps_eff", "eps_col")))
check("2 Python held: final velocities nan", all(math.isnan(v) for v in r["final_velocities"]))
check("2 Python held: the warning", any("gravity holds" in str(x.message) for x in w))
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = granwave.chain(n=3, dt=1e-3)
check("3 Python dt 1e-3: dt the step taken, dt_given 1e-3", r["dt"] == r["dt_max"] == $dtmax and r["dt_given"] == 1e-3)
check("3 Python dt 1e-3: the warning", any("dt 0.001 s is above dt_max" in str(x.message) for x in w))
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = granwave.drop(n=3, dt=1e-3)
check("3 Python drop dt 1e-3: dt the step taken, dt_given 1e-3", r["dt"] == r["dt_max"] and r["dt_given"] == 1e-3)
check("3 Python drop dt 1e-3: the warning", any("dt 0.001 s is above dt_max" in str(x.message) for x in w))
EOF

test_summary test_chain_located_outcomes
