#!/bin/bash
# test_no_effect_drag_studies.sh GRANWAVE SRCDIR: the studies' "no effect"
# check of the sensor body's dashpot and the guide's friction (the forty-second
# session left it to chain and drop: falcon, wavespeed and softwall given
# --sensor-damping 1e-12 or --guide-friction 1e-15 ran in silence). Each study
# tallies the predicted effect over its columns (sensor: zeta = c/(2 sqrt(k_s
# m_s)); guide: (F_c/v + c_g) t_col/m at each column's size and speed, its
# wall's stiffness for softwall) and warns once, on stderr and in --json, when
# even the largest is below rtol, naming how many columns:
#  1 falcon --sensor-damping 1e-12: warned; its F_max (mean, least, largest),
#    T_q and tau_N those of --sensor-damping 1e-30 to 1e-11 relative (the
#    warning is true; any dashpot at all moves RK4's steps, 2.4e-7 from none,
#    as test_no_effect_drag found for chain); --sensor-damping 10 (zeta 0.016)
#    not warned.
#  2 wavespeed --guide-friction 1e-15: warned, --json too; --guide-friction
#    1e-3 not warned.
#  3 softwall --sensor-damping 1e-12 --guide-viscous 1e-15: both warned, once
#    each; --guide-viscous 1e-2 not warned.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$2/tests/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

SB="--sensor-mass 1e-2 --sensor-stiffness 1e7"
F="falcon --n 1:3 --vimp 0.3 --heights none --quiet"
W="wavespeed --n 6:8 --vimp 0.3 --quiet"
S="softwall --n 1:3 --quiet"
# warned FILE WHAT: the lines of FILE that say WHAT has no effect
warned() { grep -c "warning: the $2.* has no effect" "$1"; }

# --- 1 falcon ---
timeout 300 "$GW" $F $SB --sensor-damping 1e-12 >/dev/null 2>f1.err; rc=$?
if [ $rc -eq 0 ] && [ "$(warned f1.err "sensor body's dashpot")" -eq 1 ] &&
    grep -q "granwave falcon: warning: the sensor body's dashpot (--sensor-damping 1e-12 N s/m) has no effect: its damping ratio c/(2 sqrt(k_s m_s)) = 1.58e-15 (the largest over the study's 3 columns) is below the solver's rtol" f1.err; then
    ok "1 falcon --sensor-damping 1e-12 warned: $(grep -o 'its damping ratio.*rtol [^,]*' f1.err)"
else
    ko "1 falcon --sensor-damping 1e-12: exit $rc, '$(head -c 400 f1.err)'"
fi
timeout 300 "$GW" $F $SB --sensor-damping 1e-12 --json >f1.json 2>/dev/null
timeout 300 "$GW" $F $SB --sensor-damping 1e-30 --json >f0.json 2>/dev/null
if /usr/bin/python3 - f1.json f0.json <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
keys = ("f_max_mean", "f_max_min", "f_max_max", "t_q", "tau_n_last")
fa = [a["velocities"][0][k] for k in keys]
fb = [b["velocities"][0][k] for k in keys]
assert all(abs(x - y) <= 1e-11 * abs(y) for x, y in zip(fa, fb)), (fa, fb)
assert sum("dashpot" in w and "has no effect" in w for w in a["warnings"]) == 1, a["warnings"]
PY
then
    ok "  its F_max, T_q and tau_N those of --sensor-damping 1e-30 to 1e-11, and the warning in --json"
else
    ko "  falcon --sensor-damping 1e-12 --json: F_max or warnings differ"
fi
timeout 300 "$GW" $F $SB --sensor-damping 10 >/dev/null 2>f2.err; rc=$?
if [ $rc -eq 0 ] && ! grep -q "no effect" f2.err; then
    ok "  control: falcon --sensor-damping 10 (zeta 0.016) not warned"
else
    ko "  falcon --sensor-damping 10: exit $rc, '$(head -c 300 f2.err)'"
fi
# --- 2 wavespeed ---
timeout 300 "$GW" $W --guide-friction 1e-15 >/dev/null 2>w1.err; rc=$?
if [ $rc -eq 0 ] && [ "$(warned w1.err "guide's friction")" -eq 1 ] &&
    grep -q "granwave wavespeed: warning: the guide's friction (--guide-friction 1e-15 N, --guide-viscous 0 N s/m) has no effect: .* (the largest over the study's 3 columns), is below the solver's rtol" w1.err; then
    ok "2 wavespeed --guide-friction 1e-15 warned: $(grep -o 't_col/m = [^)]*)' w1.err)"
else
    ko "2 wavespeed --guide-friction 1e-15: exit $rc, '$(head -c 400 w1.err)'"
fi
timeout 300 "$GW" $W --guide-friction 1e-15 --json 2>/dev/null >w1.json
if /usr/bin/python3 -c 'import json, sys; d = json.load(open("w1.json")); sys.exit(sum("friction" in w and "has no effect" in w for w in d["warnings"]) != 1)'; then
    ok "  and in --json"
else
    ko "  wavespeed --json: the warning missing"
fi
timeout 300 "$GW" $W --guide-friction 1e-3 >/dev/null 2>w2.err; rc=$?
if [ $rc -eq 0 ] && ! grep -q "has no effect" w2.err; then
    ok "  control: wavespeed --guide-friction 1e-3 not warned"
else
    ko "  wavespeed --guide-friction 1e-3: exit $rc, '$(head -c 300 w2.err)'"
fi
# --- 3 softwall ---
timeout 300 "$GW" $S $SB --sensor-damping 1e-12 --guide-viscous 1e-15 >/dev/null 2>s1.err; rc=$?
if [ $rc -eq 0 ] && [ "$(warned s1.err "sensor body's dashpot")" -eq 1 ] && [ "$(warned s1.err "guide's friction")" -eq 1 ] &&
    grep -q "^granwave softwall: warning: the sensor body's dashpot (--sensor-damping 1e-12 N s/m) has no effect" s1.err; then
    ok "3 softwall --sensor-damping 1e-12 --guide-viscous 1e-15: both warned once"
else
    ko "3 softwall: exit $rc, '$(head -c 500 s1.err)'"
fi
timeout 300 "$GW" $S --guide-viscous 1e-2 >/dev/null 2>s2.err; rc=$?
if [ $rc -eq 0 ] && ! grep -q "has no effect" s2.err; then
    ok "  control: softwall --guide-viscous 1e-2 not warned"
else
    ko "  softwall --guide-viscous 1e-2: exit $rc, '$(head -c 300 s2.err)'"
fi
test_summary test_no_effect_drag_studies
