#!/bin/bash
# test_hostile_thirtyfourth.sh GRANWAVE SRCDIR: what the thirty-fourth hostile
# pass found, fixed at its root and asserted here.
#  1 A plastic wall (--sheet-law material with a yield stress) under the
#    implicit methods. Its largest overlap D_max follows D through a C^1 ramp
#    whose top edge was where tracking sits (D = D_max). The difference
#    quotients of the Jacobian push D_max up by 1.5e-8 of its scale, onto the
#    ramp, and found a slope of about -1e9 /s that the rate does not have on
#    the other side: Newton then contracted by only 1/(1 + gamma slope) an
#    iteration. `chain --n 1 --sheet pmma --sheet-law material --sheet-yield
#    1e6` took 252 steps under arkode erk, 180,000 under cvode bdf, and arkode
#    dirk and imex crawled at steps of about 1e-10 s (about 8 minutes by the
#    progress lines; falcon studies of such a wall said nothing for minutes).
#    So did the brass and beech sheets' own material law (plastic by default:
#    `chain --n 3 --sheet brass --sheet-law material --solver arkode --method
#    dirk` past 10 s, 0.2 s now; cvode bdf 34,280 steps, 1354 now).
#    The ramp now ends dtrack below D_max: tracking lies on its flat top.
# The checks compare solvers on one input: step counts (deterministic), not
# times; the timeouts only stop the runs the old code does not end.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

WALL="--sheet pmma --sheet-law material --sheet-yield 1e6"
# agree F K TOL: the value K of F within a relative TOL of erk's (e.json)
agree() { jq_py "$1" "abs(d['$2'] - $(jq_py e.json "d['$2']")) <= $3 * abs($(jq_py e.json "d['$2']"))"; }

# --- one bead on the plastic wall: every implicit method ends, as erk does ---
# shellcheck disable=SC2086
if runs_json "n 1 plastic wall, arkode erk (the reference)" e.json chain --n 1 $WALL --solver arkode --method erk --quiet; then
    erk_steps=$(jq_py e.json "d['steps']")
    for m in "arkode dirk" "arkode imex" "cvode bdf"; do
        set -- $m
        # shellcheck disable=SC2086
        runs_json "n 1 plastic wall, $1 $2: ends within 60 s" i.json chain --n 1 $WALL --solver "$1" --method "$2" --quiet || continue
        # F_max within 1e-7 of erk's: cvode adams, which the fix does not touch, is
        # 2.9e-8 from it at the same 1e-12 tolerances (imex 2e-9, bdf 8e-11, dirk
        # 6e-12); tau_N within 1e-9 (all within 2e-11); the energy ledger closes
        # as erk's does (5e-13; bdf 2.5e-10)
        v=$(jq_py i.json "d['energy_error'] < 1e-8")
        if [ "$(agree i.json f_max 1e-7)" = True ] && [ "$(agree i.json tau_n 1e-9)" = True ] && [ "$v" = True ]; then
            ok "n 1 plastic wall, $1 $2: F_max within 1e-7 and tau_N within 1e-9 of erk's, energy error below 1e-8"
        else
            ko "n 1 plastic wall, $1 $2: F_max $(jq_py i.json "d['f_max']") (erk $(jq_py e.json "d['f_max']")), energy error $(jq_py i.json "d['energy_error']")"
        fi
        # the number of steps: 2 to 40 times erk's measured after the fix (bdf
        # 446, dirk 4832, imex 6581 against 252), 700 times before (bdf)
        s=$(jq_py i.json "d['steps']")
        [ "$s" -le $((50 * erk_steps)) ] && ok "n 1 plastic wall, $1 $2: $s steps, at most 50 times erk's $erk_steps" ||
            ko "n 1 plastic wall, $1 $2: $s steps against erk's $erk_steps"
    done
fi

# --- five beads: bead 1 reloads the wall; cvode bdf as many steps as erk about ---
# shellcheck disable=SC2086
if runs_json "n 5 plastic wall, arkode erk" e.json chain --n 5 $WALL --solver arkode --method erk --quiet &&
    runs_json "n 5 plastic wall, cvode bdf" i.json chain --n 5 $WALL --solver cvode --method bdf --quiet; then
    s=$(jq_py i.json "d['steps']") erk_steps=$(jq_py e.json "d['steps']")
    # measured 2966 against 1494; 372,195 before
    [ "$s" -le $((10 * erk_steps)) ] && ok "n 5 plastic wall, cvode bdf: $s steps, at most 10 times erk's $erk_steps" ||
        ko "n 5 plastic wall, cvode bdf: $s steps against erk's $erk_steps"
    [ "$(agree i.json f_max 1e-8)" = True ] && [ "$(agree i.json eps_eff 1e-8)" = True ] &&
        ok "n 5 plastic wall, cvode bdf: F_max and eps_eff within 1e-8 of erk's" ||
        ko "n 5 plastic wall, cvode bdf: F_max $(jq_py i.json "d['f_max']") against $(jq_py e.json "d['f_max']")"
fi

# --- with a sensor body (its states ordered before the beads) under dirk ---
S="--sensor-mass 1e-3 --sensor-stiffness 1e9"
# shellcheck disable=SC2086
if runs_json "n 2 sensor body on a plastic wall, arkode erk" e.json chain --n 2 $S $WALL --solver arkode --method erk --quiet &&
    runs_json "n 2 sensor body on a plastic wall, arkode dirk: ends within 60 s" i.json chain --n 2 $S $WALL --solver arkode --method dirk --quiet; then
    # the sensor's reading peaks on its own ringing (1e6 rad/s, 0.02 N, about
    # 600 periods), which the implicit methods resolve at these tolerances to
    # about 1.4e-7: against the converged 3.6587982845 N (erk and dirk at
    # --dt-max 1e-8 agree within 3e-11) dirk is 1.36e-7 low and cvode bdf
    # 1.18e-7 (also before issue 18's fix of the wall's Jacobian), erk 3.6e-9
    # high. Dirk's error falls as its step to the fifth power (--dt-max 1.3e-7:
    # 6.4e-9) and with its tolerance (1e-13: 1.4e-8). Before, its Newton
    # failures on the wall's kink cut its steps (28,238 against 17,645 now)
    # and it was 3.3e-9 low. So 2e-7
    [ "$(agree i.json f_max 2e-7)" = True ] && [ "$(agree i.json tau_n 1e-9)" = True ] &&
        ok "n 2 sensor body on a plastic wall, dirk: F_max within 2e-7 and tau_N within 1e-9 of erk's" ||
        ko "n 2 sensor body on a plastic wall, dirk: F_max $(jq_py i.json "d['f_max']") against $(jq_py e.json "d['f_max']")"
fi

# --- the sheets whose material law is plastic by default (brass, beech) ---
for sh in brass beech; do
    runs_json "n 3 on the $sh sheet's own law, arkode erk" e.json chain --n 3 --sheet $sh --sheet-law material --solver arkode --method erk --quiet || continue
    runs_json "n 3 on the $sh sheet's own law, arkode dirk: ends within 60 s" i.json chain --n 3 --sheet $sh --sheet-law material --solver arkode --method dirk --quiet || continue
    # measured 1400 and 1823 dirk steps against erk's 583 and 896; F_max within 1e-11
    s=$(jq_py i.json "d['steps']") erk_steps=$(jq_py e.json "d['steps']")
    [ "$s" -le $((10 * erk_steps)) ] && [ "$(agree i.json f_max 1e-7)" = True ] &&
        ok "n 3 on the $sh sheet's own law, dirk: $s steps (erk $erk_steps), F_max within 1e-7 of erk's" ||
        ko "n 3 on the $sh sheet's own law, dirk: $s steps against erk's $erk_steps, F_max $(jq_py i.json "d['f_max']")"
done

# --- a falcon study of such a wall under dirk ends (it said nothing for minutes) ---
# shellcheck disable=SC2086
timeout -s KILL 60 "$GW" falcon --n 1:2 --heights none $WALL --solver arkode --method dirk --json --quiet >f.json 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 0 ] && [ "$(jq_py f.json "d['unfinished'] == 0 and len(d['velocities']) == 1" 2>/dev/null)" = True ] &&
    ok "falcon --n 1:2 on a plastic wall under dirk: both columns within 60 s" ||
    ko "falcon --n 1:2 on a plastic wall under dirk: exit $rc ($(head -c 300 "$tmp/stderr"))"

test_summary test_hostile_thirtyfourth
