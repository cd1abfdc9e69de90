#!/bin/bash
# test_no_effect_drag_sweep.sh GRANWAVE SRCDIR: a chain sweep's "no effect"
# check of the sensor body's dashpot and the guide's friction (the forty-third
# session gave it to falcon, wavespeed and softwall; a sweep given
# sensor-damping = 1e-12 on a 1e-2 kg, 1e7 N/m sensor ran in silence). The
# sweep's check pass tests each case with the single run's rule against the
# case's own rtol (sensor: zeta = c/(2 sqrt(k_s m_s)); guide: (F_c/v + c_g)
# t_col/m at the case's size and speed) and says once over the sweep, for
# each, in how many of its cases it has no effect, the largest such effect
# and the first such case, naming the config's keys (sensor-damping, no
# dashes), in the run and under --check (nothing written):
#  1 n = 1, 3 by sensor-damping = 1e-12, 10: "in 2 of 4 cases (the first,
#    case 0)", at most 1.58e-15, once; --check alike, nothing written; the
#    warned rows (f_max, eps_eff, tau_n) are those of sensor-damping = 1e-30
#    to 1e-11 relative (the warning is true).
#  2 vimp = 0.2, 0.3 by guide-viscous = 1e-15, 1e-2 at guide-friction 1e-15:
#    "the guide's friction has no effect in 2 of 4 cases (the first, case 0)".
#  Controls: a dashpot that acts (sensor-damping = 10, 100: zeta 0.016,
#  0.16), a sensor body without a dashpot and the default column say "no
#  effect" nowhere; the sweep's own contact-damping line is not doubled.
# Python's sweep: tests/python/test_no_effect_drag_sweep_py.py.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# sweep_config NAME MODEL GRID PARAMS, sweep_dashpot_config NAME [DAMPING]
# (1 below) and sweep_quiet NAME [FLAGS] (NAME.ini into NAME.out, stderr in
# NAME.err, sets rc): test_lib.sh's
# said NAME WHAT: the lines of NAME.err saying the WHAT has no effect
said() { grep -c "^granwave sweep: warning: the $2 has no effect" "$1.err"; }
# column NAME COL: the table's column COL, one value a line
column() {
    awk -F, -v want="$2" '/^#/ { next } !h { for (i = 1; i <= NF; i++) if ($i == want) c = i; h = 1; next }
        { print $c }' "$1.out/results.csv"
}

SB="sensor-mass = 1e-2;sensor-stiffness = 1e7;vimp = 0.3"
# --- 1 the sensor's dashpot ---
sweep_dashpot_config s1
sweep_quiet s1
if [ $rc -eq 0 ] && [ "$(said s1 "sensor body's dashpot")" -eq 1 ] &&
    grep -q "warning: the sensor body's dashpot has no effect in 2 of 4 cases (the first, case 0): its damping ratio c/(2 sqrt(k_s m_s)), at most 1.58e-15 there, is below the case's rtol, and their rows are those of sensor-damping 0 (give a larger sensor-damping)$" s1.err; then
    ok "1 sensor-damping = 1e-12, 10 over n = 1, 3: warned once, 2 of 4 cases, the first case 0, at most 1.58e-15"
else
    ko "1 sensor-damping = 1e-12, 10: exit $rc, '$(head -c 500 s1.err)'"
fi
cp s1.ini k1.ini
sweep_quiet k1 --check
if [ $rc -eq 0 ] && [ "$(said k1 "sensor body's dashpot")" -eq 1 ] && grep -q "in 2 of 4 cases (the first, case 0)" k1.err &&
    [ ! -e k1.out ]; then
    ok "  sweep --check warns alike, nothing written"
else
    ko "  sweep --check: exit $rc, '$(head -c 400 k1.err)'"
fi
sweep_dashpot_config s0 1e-30
sweep_quiet s0
bad=""
for col in f_max eps_eff tau_n; do
    paste -d' ' <(column s1 "$col") <(column s0 "$col") | sed -n '1p;3p' | # the cases at 1e-12, 1e-30
        awk '{ d = $1 - $2; if (d < 0) d = -d; if (!(d <= 1e-11 * ($2 < 0 ? -$2 : $2))) exit 1 }' || bad="$bad $col"
done
if [ $rc -eq 0 ] && [ -z "$bad" ] && [ "$(column s1 f_max | wc -l)" -eq 4 ]; then
    ok "  the warned rows are those of sensor-damping 1e-30 to 1e-11 (f_max, eps_eff, tau_n)"
else
    ko "  the rows at 1e-12 against 1e-30: exit $rc, differ:$bad"
fi
# --- 2 the guide's friction ---
sweep_config g1 chain "vimp = 0.2, 0.3;guide-viscous = 1e-15, 1e-2" "n = 3;guide-friction = 1e-15"
sweep_quiet g1
if [ $rc -eq 0 ] && [ "$(said g1 "guide's friction")" -eq 1 ] &&
    grep -q "warning: the guide's friction has no effect in 2 of 4 cases (the first, case 0): its predicted relative effect on the impact, (F_c/v + c_g) t_col/m, at most [0-9.e-]* there, is below the case's rtol.*(give a larger guide-friction or guide-viscous)$" g1.err; then
    ok "2 guide-viscous = 1e-15, 1e-2 at guide-friction 1e-15: warned once, 2 of 4 cases, the first case 0"
else
    ko "2 guide-viscous = 1e-15, 1e-2: exit $rc, '$(head -c 500 g1.err)'"
fi
# --- controls ---
sweep_config c1 chain "n = 1, 3;sensor-damping = 10, 100" "$SB;guide-viscous = 1e-2"
sweep_quiet c1
[ $rc -eq 0 ] && ! grep -q "no effect" c1.err &&
    ok "control: sensor-damping = 10, 100 (zeta 0.016, 0.16) and guide-viscous 1e-2 not warned" ||
    ko "control: a dashpot that acts: exit $rc, '$(head -c 300 c1.err)'"
sweep_config c2 chain "n = 1, 3" "$SB"
sweep_quiet c2
[ $rc -eq 0 ] && ! grep -q "no effect" c2.err && ok "control: a sensor body without a dashpot not warned" ||
    ko "control: a sensor body without a dashpot: exit $rc, '$(head -c 300 c2.err)'"
sweep_config c3 chain "n = 1, 3" "vimp = 0.3"
sweep_quiet c3
[ $rc -eq 0 ] && [ ! -s c3.err ] && ok "control: the default column warns of nothing" ||
    ko "control: the default column: exit $rc, '$(head -c 300 c3.err)'"
sweep_config c4 chain "n = 3, 4" "$SB;damping = kk;gamma = 1e-8;sensor-damping = 1e-12"
sweep_quiet c4
[ $rc -eq 0 ] && [ "$(grep -c "no effect" c4.err)" -eq 2 ] && [ "$(said c4 "sensor body's dashpot")" -eq 1 ] &&
    grep -q "warning: the contact damping has no effect in 2 of 2 cases" c4.err &&
    ok "the contact damping's line and the dashpot's, one each (2 of 2 cases)" ||
    ko "damping kk gamma 1e-8 with sensor-damping 1e-12: exit $rc, '$(head -c 500 c4.err)'"
test_summary test_no_effect_drag_sweep
