#!/bin/bash
# test_chain_band_order.sh GRANWAVE SRCDIR: a column's states that couple only to
# bead 1 (a sensor body's x_s, v_s; a plastic or viscoelastic wall's work,
# largest overlap and Maxwell arms) are stored after the beads; in that order
# they made the implicit methods' band the whole system (n^2 memory: at most
# 3339 beads; dim^3 a factorisation: 40 s at n = 100 on a 1e-3 kg body on 1e9
# N/m under cvode bdf, and the plan refused such columns above about 167
# beads). The implicit methods now order them before the beads (gw_system
# lead0, nlead) and leave the dissipated energy's ledger row out (nledger).
# Asserted:
#  1 a column the plan refused as the whole band's work (n = 40 at --dt-max
#    5e-8: 1.4e8 steps x states^2) runs under cvode bdf and agrees with arkode
#    erk (no Jacobian): F_max within 1e-6, tau_N within 2e-9 and the
#    restitution within 1e-9 (measured 2.6e-9, 8e-10 and 2e-11; tau_N is
#    bdf's own error at 1e-12 over 1.07 ms, 1.0e-9 since a force maximum no
#    longer restarts the solver, 1.75e-10 at rtol = atol = 1e-13);
#  2 arkode dirk and imex on a 1e-3 kg body damped at 1e7 N s/m (dirk failed
#    with exit 1 before: error test failures at 5.1e-5 s) agree with cvode bdf
#    within 1e-6 on F_max, tau_N and the restitution (the time of the peak,
#    a flat maximum, differs by 5e-5 between the solvers);
#  3 the widest band: a viscoelastic or plastic sheet (--sheet-law material:
#    the work, D_max or up to 7 arms) on a sensor body with contact damping
#    (a ledger) under cvode bdf and arkode dirk agrees with cvode adams (no
#    matrix) within 1e-6 on F_max, tau_N and the restitution;
#  4 a drop of 5000 beads on a sensor body (memory refused at 3339 before)
#    runs to its t-max (the memory bound's own refusal, now at about 2.16
#    million beads, is asserted in test_hostile_chain).
# 1, 2 and 4 fail on the code before.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
SB="--sensor-mass 1e-3 --sensor-stiffness 1e9"

# agree A.json B.json TOL KEY...: every KEY within TOL relative
agree() {
    /usr/bin/python3 - "$@" <<'PYEOF'
import json, sys
a, b, tol = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), float(sys.argv[3])
bad = [f"{k} {a[k]!r} against {b[k]!r}" for k in sys.argv[4:]
       if not (a[k] is not None and b[k] is not None and abs(a[k] / b[k] - 1) <= tol)]
print("; ".join(bad) if bad else "True")
PYEOF
}

# --- 1 past the whole band's work bound, cvode bdf against arkode erk ---
if runs_json "chain --n 40 on a sensor body at --dt-max 5e-8 (cvode bdf)" b40.json chain --n 40 $SB --dt-max 5e-8 &&
    runs_json "the same under arkode erk" e40.json chain --n 40 $SB --dt-max 5e-8 --solver arkode; then
    v=$(agree b40.json e40.json 1e-6 f_max) w=$(agree b40.json e40.json 2e-9 tau_n)$(agree b40.json e40.json 1e-9 eps_eff)
    [ "$v" = True ] && [ "$w" = TrueTrue ] &&
        ok "n = 40 on a sensor body (refused before as the whole band's work): cvode bdf agrees with arkode erk" ||
        ko "n = 40 on a sensor body: $v $w"
fi

# --- 2 arkode's implicit methods on a damped sensor body ---
D="--n 3 $SB --sensor-damping 1e7"
if runs_json "chain $D (cvode bdf)" d_bdf.json chain $D; then
    for m in dirk imex; do
        runs_json "chain $D (arkode $m)" "d_$m.json" chain $D --solver arkode --method $m || continue
        v=$(agree "d_$m.json" d_bdf.json 1e-6 f_max tau_n eps_eff)
        [ "$v" = True ] && ok "arkode $m on a sensor body damped at 1e7 agrees with cvode bdf" || ko "arkode $m: $v"
    done
fi

# --- 3 the widest band: a sheet's own states, a sensor body and a ledger ---
for sheet in rubber tape; do
    W="--n 12 --sheet $sheet --sheet-law material --sensor-mass 1e-2 --sensor-stiffness 1e8 --damping kk --restitution 0.9"
    runs_json "chain $W (cvode adams)" "w_adams_$sheet.json" chain $W --solver cvode --method adams || continue
    for s in "cvode bdf" "arkode dirk"; do
        set -- $s
        f="w_$2_$sheet.json"
        runs_json "chain $W ($s)" "$f" chain $W --solver "$1" --method "$2" || continue
        v=$(agree "$f" "w_adams_$sheet.json" 1e-6 f_max tau_n eps_eff)
        [ "$v" = True ] && ok "a $sheet sheet on a damped column and a sensor body: $s agrees with cvode adams" ||
            ko "a $sheet sheet, $s: $v"
    done
done

# --- 4 a drop above the whole band's memory bound ---
timeout -s KILL 120 "$GW" drop --n 5000 $SB --t-max 1e-6 --json >drop.json 2>"$tmp/stderr" </dev/null
rc=$?
if [ $rc -eq 0 ] && [ "$(jq_py drop.json "d['n']")" = 5000 ]; then
    ok "drop --n 5000 on a sensor body runs (memory refused at 3339 beads before)"
else
    ko "drop --n 5000 on a sensor body: exit $rc: $(head -c 300 "$tmp/stderr")"
fi

test_summary test_chain_band_order
